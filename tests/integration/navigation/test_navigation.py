"""amcl and move_base on turtlebot3_world with a map drawn from the world file (world_map), through their real
interfaces: the move_base action's goal/result topics, /move_base/cancel, /scan, /odom and /amcl_pose.

One master, simulator and navigation stack for the module; the simulator runs at REAL_TIME_FACTOR and every
wait is in sim time. """
import pytest

from roslab.nav_goals import send_goal, wait_result

from .stack import start_navigation, turtlebot3_world_cells

REAL_TIME_FACTOR = 10
PREEMPTED, SUCCEEDED, ABORTED = 2, 3, 4


@pytest.fixture(scope="module")
def nav(ros_master, tmp_path_factory):
    return start_navigation(ros_master, tmp_path_factory.mktemp("map"), turtlebot3_world_cells(), REAL_TIME_FACTOR,
                            (("/move_base/result", "move_base_msgs/MoveBaseActionResult"),
                             ("/odom", "nav_msgs/Odometry"),
                             ("/amcl_pose", "geometry_msgs/PoseWithCovarianceStamped")))


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

