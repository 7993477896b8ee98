"""amcl and move_base on turtlebot3_world with a map drawn from the world file (world_map), through their real
interfaces: the move_base action's goal/result topics, /move_base/cancel, /scan, /odom and /amcl_pose.

One master, simulator and navigation stack for the module; the simulator runs at REAL_TIME_FACTOR and every
wait is in sim time. """
from pathlib import Path

import pytest

from roslab import wait_for_service, wait_for_topic
from roslab.nav_goals import send_goal, wait_result

from . import world_map

HERE = Path(__file__).resolve().parent
REAL_TIME_FACTOR = 10
SPAWN = (-2.0, -0.5)
PREEMPTED, SUCCEEDED, ABORTED = 2, 3, 4


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

