"""COM2009 Part 3 Exercise 3 as the course runs it: the course's navigation.launch (nav_world, map_server, amcl from
the START zone, move_base, a required rviz) on a map of nav_world, then `rostopic pub /move_base_simple/goal
geometry_msgs/PoseStamped` with tab completion's YAML (frame 'map', orientation w 1.0) to each zone A-D in turn:
move_base says "Goal reached." with the robot inside the zone's circle.

The map is drawn from the world file and written by map_saver's own writer (world_map), standing in for the map a
student saves after SLAM: SLAM and map_saver in nav_world are test_turtlebot3_slam's, and the whole sequence, SLAM
included, is tests/bench/part3_bench.py (143 s wall at load 11, over this module's budget).
"""
import pytest

from roslab.mapping_routes import ROUTES

from . import part3, world_map

REAL_TIME_FACTOR = 10


@pytest.fixture(scope="module")
def navigation(ros_master, tmp_path_factory):
    route = ROUTES["nav_world"]
    cells = world_map.world_cells("nav_world", route.spawn[:2], world_path=route.world_path())
    map_yaml = world_map.write_map(tmp_path_factory.mktemp("map"), "nav_map", cells)
    return part3.start_navigation(ros_master, map_yaml, REAL_TIME_FACTOR)


@pytest.mark.parametrize("zone", list(part3.ZONES))
def test_rostopic_pub_goal_reaches_the_zone(ros_master, navigation, zone):
    result = part3.go_to_zone(ros_master, navigation, zone)
    assert result["text"] == "Goal reached." and part3.reached(result), result
