"""Goals reached, and amcl converging, on turtlebot3_world at real time: amcl and move_base with a map drawn from
the world file (world_map), goals through the move_base action's topics, the truth from /gazebo/get_model_state.

These run at REAL_TIME_FACTOR 1 and are marked realtime: move_base's 10 Hz control costs about a third of a core
at real time (DWA's trajectories and a plan at 5 Hz), so at factor 2 on a loaded machine, and at 10 anywhere, its
commands come late, the robot touches pillars and then cannot plan out of their inscribed cells (the real
move_base in a Gazebo run faster than real time does the same). tests/bench/nav_bench.py runs the 40 goals.
"""
import math

import pytest

from roslab import nav_goals

from . import world_map
from .stack import start_navigation, turtlebot3_world_cells

REAL_TIME_FACTOR = 1
GOALS, SEED = 3, 30
# The path driven over the shortest grid path, summed over the goals: 1.17 on an idle machine, 1.20 beside another
# realtime module (navfn's path keeps away from pillars, and the turn at each start adds to it); the bench reports
# the 1.2 per goal (median 1.18). This bound catches a detour, not the last few percent.
PATH_RATIO = 1.3
CONTACT_MARGIN_M = 0.02      # nothing nearer the body than this on /scan
# Where the simulator has the robot at "Goal reached.": move_base judges xy_goal_tolerance (0.05 m) and
# yaw_goal_tolerance (0.17 rad) on amcl's estimate, which after a drive with turns is off by up to 0.165 m
# (measured at the second goal, on the arena's east side), more than its 0.05 m after a straight 2 m.
TRUE_XY_M, TRUE_YAW_RAD = 0.25, 0.3
AMCL_OFFSET = (0.3, math.radians(15.0))
AMCL_XY_M, AMCL_YAW_RAD = 0.05, math.radians(3.0)


@pytest.fixture(scope="module")
def cells():
    return turtlebot3_world_cells()


@pytest.fixture(scope="module")
def nav(ros_master, cells, tmp_path_factory):
    """The stack's probe; nav_goals.true_pose asks the simulator from this process, through the ROS_MASTER_URI
    the ros_master fixture set."""
    return start_navigation(ros_master, tmp_path_factory.mktemp("map"), cells, REAL_TIME_FACTOR,
                            (("/move_base/result", "move_base_msgs/MoveBaseActionResult"),
                             ("/move_base/feedback", "move_base_msgs/MoveBaseActionFeedback"),
                             ("/odom", "nav_msgs/Odometry"), ("/scan", "sensor_msgs/LaserScan"),
                             ("/amcl_pose", "geometry_msgs/PoseWithCovarianceStamped")))


@pytest.mark.realtime
def test_amcl_started_off_the_true_pose_converges_after_2_m(nav):
    error_m, error_rad = nav_goals.amcl_error_after_drive(nav, *AMCL_OFFSET, 0.2, 10.0)
    assert error_m <= AMCL_XY_M and error_rad <= AMCL_YAW_RAD, (error_m, math.degrees(error_rad))


@pytest.mark.realtime
def test_seeded_random_goals_are_reached_without_contact(nav, cells):
    costs = nav_goals.global_costs(world_map.GEOMETRY, cells)
    goals = nav_goals.random_goals(cells, costs, world_map.GEOMETRY, nav_goals.true_pose()[:2], GOALS, SEED)
    driven = shortest = 0.0
    for goal in goals:
        run = nav_goals.drive_to(nav, goal)
        x, y, yaw = nav_goals.true_pose()
        where = f"goal ({goal[0]:.2f}, {goal[1]:.2f}): {run}, truth ({x:.2f}, {y:.2f}, {yaw:.2f})"
        assert run["text"] == "Goal reached.", where
        assert math.hypot(x - goal[0], y - goal[1]) <= TRUE_XY_M, where
        assert abs(math.remainder(yaw - goal[2], math.tau)) <= TRUE_YAW_RAD, where
        assert run["clearance"] >= CONTACT_MARGIN_M, where
        driven, shortest = driven + run["driven"], shortest + goal[3]
    assert driven <= PATH_RATIO * shortest, (driven, shortest)

