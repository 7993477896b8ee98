"""Goals reached, and amcl converging, on turtlebot3_world at twice real time: amcl and move_base with a map drawn from
the world file (world_map), goals through the move_base action's topics, the truth from /gazebo/get_model_state;
last, a box spawned across the lane the robot drives is driven round and marked in the global costmap.

These run at REAL_TIME_FACTOR 2 and are marked realtime (3 of 3 passed in 63-72 s at load ~5; at factor 1 the
module took 109 s). Per second of sim time move_base costs about a quarter of a core (its planners a fraction of
that since they were vectorised; the rest is rospy's /clock, /tf and message handling) and amcl about a tenth, so on
a 2-core machine at load 11-23 even factor 2 starves them: amcl lost the robot by 3 m, and at factor 3 (load 16)
missed its 0.05 m. tests/bench/nav_bench.py runs 20 goals at real time and reports the highest factor at which
goals are still reached (3 at load ~8).
"""
import math

import numpy as np
import pytest
import rospy
from gazebo_msgs.srv import SpawnModel
from geometry_msgs.msg import Pose

from roslab import nav_goals
from tb3_sim.core.model_xml import box_sdf

from . import world_map
from .stack import start_navigation, turtlebot3_world_cells

REAL_TIME_FACTOR = 2
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
# The lane between the pillars at (0, 0) and (0, -1.1): the robot drives from its west end to its east end, and a
# box across its middle, spawned once the goal is sent, closes it (gaps to the pillars under the footprint's
# width), so the way round is the next lane north or south (~2.2 m more).
LANE_START, LANE_GOAL = (-1.65, -0.55, 0.0), (1.65, -0.55, 0.0)
BOX_XY, BOX_SIZE = (0.0, -0.55), (0.2, 0.5, 0.4)
ROBOT_HALF_WIDTH_M = 0.15   # the waffle's half width is 0.155 m; nearer to the box than this would be a contact


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



def spawn_box(name, x, y, size):
    pose = Pose()
    pose.position.x, pose.position.y, pose.orientation.w = x, y, 1.0
    reply = rospy.ServiceProxy("/gazebo/spawn_sdf_model", SpawnModel)(
        model_name=name, model_xml=box_sdf(name, *size), initial_pose=pose, reference_frame="")
    assert reply.success, reply.status_message


@pytest.mark.realtime
def test_a_box_spawned_across_the_planned_path_is_driven_around_and_marked(nav, cells):
    start = nav_goals.drive_to(nav, LANE_START + (0.0,))
    assert start["text"] == "Goal reached.", start
    costs = nav_goals.global_costs(world_map.GEOMETRY, cells)
    straight = nav_goals.shortest_grid_path_m(costs, world_map.GEOMETRY, LANE_START, LANE_GOAL)
    assert straight < 3.4   # the lane itself is the shortest way
    for topic in ("/odom", "/scan", "/move_base/feedback"):
        nav.take(topic)
    goal_id = nav_goals.send_goal(nav, *LANE_GOAL)
    nav.sleep_sim(1.0, 30)
    spawn_box("lane_box", *BOX_XY, BOX_SIZE)
    status, text, waited = nav_goals.wait_result(nav, goal_id)
    odom = [(e["msg"]["pose"]["pose"]["position"]["x"], e["msg"]["pose"]["pose"]["position"]["y"])
            for e in nav.take("/odom")]
    clearance = nav_goals.closest_clearance_m([e["msg"] for e in nav.take("/scan")])
    x, y, _ = nav_goals.true_pose()
    where = f"{text} after {waited:.1f} s, truth ({x:.2f}, {y:.2f}), clearance {clearance:.3f} m"
    assert text == "Goal reached.", where
    assert math.hypot(x - LANE_GOAL[0], y - LANE_GOAL[1]) <= TRUE_XY_M, where
    assert clearance >= CONTACT_MARGIN_M, where
    # round it: the robot's centre (/odom is the world pose) never within the box grown by half the footprint
    gap = np.max(np.abs(np.array(odom) - BOX_XY) - np.array(BOX_SIZE[:2]) / 2, axis=1)
    assert gap.min() >= ROBOT_HALF_WIDTH_M, (gap.min(), nav_goals.path_length_m(odom), straight)
    # the global costmap marks the box's sides that the LiDAR saw: a new subscriber gets the whole grid
    nav.subscribe("/move_base/global_costmap/costmap", "nav_msgs/OccupancyGrid")
    grid = nav.wait_for_message("/move_base/global_costmap/costmap", 20)
    data = np.array(grid["data"], dtype=np.int16).reshape(grid["info"]["height"], grid["info"]["width"])
    half = np.array(BOX_SIZE[:2]) / 2 + world_map.GEOMETRY.resolution
    cols, rows = world_map.GEOMETRY.world_to_cell(*np.meshgrid(
        np.arange(BOX_XY[0] - half[0], BOX_XY[0] + half[0], 0.025),
        np.arange(BOX_XY[1] - half[1], BOX_XY[1] + half[1], 0.025)))
    assert np.all(np.asarray(cells)[rows, cols] == 0)   # the map has nothing there
    marked = {(c, r) for c, r in zip(cols.ravel(), rows.ravel()) if data[r, c] == 100}
    assert len(marked) >= 5, data[rows.min():rows.max() + 1, cols.min():cols.max() + 1]
