"""amcl and move_base on turtlebot3_world with a map drawn from the world file (world_map), through their real
interfaces: the move_base action's goal/result topics, /move_base/cancel, /scan, /odom and /amcl_pose.

One master, simulator and navigation stack for the module; the simulator runs at REAL_TIME_FACTOR and every
wait is in sim time. """
import math
from pathlib import Path

import pytest

from roslab import wait_for_service, wait_for_topic, wait_until

from . import world_map

HERE = Path(__file__).resolve().parent
REAL_TIME_FACTOR = 10
SPAWN = (-2.0, -0.5)
GOAL_TIMEOUT_SIM_S = 90.0
PENDING, ACTIVE, PREEMPTED, SUCCEEDED, ABORTED = 0, 1, 2, 3, 4


@pytest.fixture(scope="module")
def cells():
    return world_map.world_cells("turtlebot3_world", SPAWN)


@pytest.fixture(scope="module")
def nav(ros_master, cells, tmp_path_factory):
    map_file = world_map.write_map(tmp_path_factory.mktemp("map"), "map", cells)
    ros_master.roslaunch("turtlebot3_gazebo", "turtlebot3_world.launch", "gui:=false", "model:=waffle",
                         f"real_time_factor:={REAL_TIME_FACTOR}")
    wait_for_service(ros_master.uri, "/gazebo/get_model_state", 60)
    probe = ros_master.probe()   # started after the launch set /use_sim_time: its now() and sleep_sim are sim time
    ros_master.start(["roslaunch", "--wait", str(HERE / "navigation.launch"), f"map_file:={map_file}",
                      f"initial_pose_x:={SPAWN[0]}", f"initial_pose_y:={SPAWN[1]}"], "navigation")
    wait_for_topic(ros_master.uri, "/move_base/status", 120)
    for topic, kind in (("/move_base/result", "move_base_msgs/MoveBaseActionResult"),
                        ("/odom", "nav_msgs/Odometry"),
                        ("/amcl_pose", "geometry_msgs/PoseWithCovarianceStamped")):
        probe.subscribe(topic, kind)
    return probe


class Goals:
    counter = 0


def send_goal(probe, x, y, yaw=0.0, quaternion=None):
    """Publish a MoveBaseActionGoal with a fresh id; returns the id."""
    Goals.counter += 1
    goal_id = f"test-goal-{Goals.counter}"
    qx, qy, qz, qw = quaternion or (0.0, 0.0, math.sin(yaw / 2), math.cos(yaw / 2))
    probe.publish("/move_base/goal", "move_base_msgs/MoveBaseActionGoal", {
        "goal_id": {"id": goal_id},
        "goal": {"target_pose": {"header": {"frame_id": "map"},
                                 "pose": {"position": {"x": x, "y": y},
                                          "orientation": {"x": qx, "y": qy, "z": qz, "w": qw}}}}})
    return goal_id


def wait_result(probe, goal_id, timeout_sim_s=GOAL_TIMEOUT_SIM_S):
    """(status, text, sim seconds waited) of the goal's result message."""
    start = probe.now()
    found = []

    def done():
        for entry in probe.take("/move_base/result"):
            if entry["msg"]["status"]["goal_id"]["id"] == goal_id:
                found.append(entry["msg"]["status"])
        return bool(found) or probe.now() - start > timeout_sim_s
    wait_until(done, timeout_sim_s * 3 + 60, f"the result of {goal_id}", interval_s=0.2)
    assert found, f"no result for {goal_id} within {timeout_sim_s} s of sim time"
    return found[0]["status"], found[0]["text"], probe.now() - start


# ---- tests, in the order the robot lives through them

def test_a_zero_quaternion_is_aborted_at_once(nav):
    status, text, waited = wait_result(nav, send_goal(nav, -1.5, -0.5, quaternion=(0, 0, 0, 0)), 10)
    assert (status, text) == (ABORTED, "Aborting on goal because it was sent with an invalid quaternion")
    assert waited < 1.0


def test_a_goal_inside_a_pillar_is_aborted_after_the_recoveries(nav):
    status, text, waited = wait_result(nav, send_goal(nav, 0.0, 0.0), 120)
    assert (status, text) == (ABORTED, "Failed to find a valid plan. Even after executing recovery behaviors.")
    assert waited >= 5 * 5.0   # planner_patience before each recovery and after the last


def test_a_new_goal_preempts_and_cancel_stops_the_robot(nav):
    first = send_goal(nav, -0.55, -0.55)
    nav.sleep_sim(3.0, 60)
    second = send_goal(nav, -0.55, 0.55)
    status, text, _ = wait_result(nav, first, 10)
    assert (status, text) == (PREEMPTED, "This goal was canceled because another goal was received by the "
                                         "simple action server")
    nav.sleep_sim(3.0, 60)
    nav.publish("/move_base/cancel", "actionlib_msgs/GoalID", {})
    status, text, _ = wait_result(nav, second, 10)
    assert (status, text) == (PREEMPTED, "")
    nav.sleep_sim(1.0, 60)
    twist = nav.wait_for_message("/odom", 10)["twist"]["twist"]
    assert abs(twist["linear"]["x"]) < 0.01 and abs(twist["angular"]["z"]) < 0.01
