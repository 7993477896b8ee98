"""amcl and move_base in nav_world as COM2009 Part 3 Exercise 3 runs them: the course's navigation.launch
(part3_navigation.launch: nav_world, map_server, amcl from the START zone, move_base, a required rviz) on a map
drawn from the world file and written by map_saver's own writer (world_map), standing in for the map a student
saves after SLAM (SLAM and map_saver in nav_world are test_turtlebot3_slam's; the whole sequence, SLAM included, is
tests/bench/part3_bench.py, over a module's budget). Through their real interfaces: `rostopic pub
/move_base_simple/goal geometry_msgs/PoseStamped` with tab completion's YAML (frame 'map', orientation w 1.0) to
each zone A-D, the move_base action's goal/result topics, /move_base/cancel and /odom.

One master, simulator and navigation stack for the module; the simulator runs at REAL_TIME_FACTOR and every
wait is in sim time.
"""
import pytest
import rospy
from nav_msgs.srv import GetMap

from roslab import wait_until
from roslab.graph import subscribers
from roslab.mapping_routes import ROUTES
from roslab.nav_goals import send_goal, wait_result

from . import part3, world_map

# At 10 move_base once stood 0.06 m from zone B without "Goal reached." for 90 s of sim time, clearing costmaps and
# rotating (its control loop comes late at that factor: test_goal_reaching).
REAL_TIME_FACTOR = 5
PREEMPTED, SUCCEEDED, ABORTED = 2, 3, 4
INSIDE_WALL_4 = (0.0, -0.041)   # the centre of nav_world's wall_4, 0.03 m thick


@pytest.fixture(scope="module")
def nav(ros_master, tmp_path_factory):
    route = ROUTES["nav_world"]
    cells = world_map.world_cells("nav_world", route.spawn[:2], world_path=route.world_path())
    map_yaml = world_map.write_map(tmp_path_factory.mktemp("map"), "nav_map", cells)
    return part3.start_navigation(ros_master, map_yaml, REAL_TIME_FACTOR, (("/odom", "nav_msgs/Odometry"),))


def _map_server_follows_the_clock(master_uri):
    return "/map_server" in subscribers(master_uri, "/clock")


# ---- tests, in the order the robot lives through them

def test_map_server_follows_the_clock_only_while_it_answers(ros_master, nav):
    """map_server stamps its map once: between calls it does not take /clock's 100 messages a sim second, and a
    call still logs with the current sim time."""
    assert not _map_server_follows_the_clock(ros_master.uri)
    nav.subscribe("/rosout_agg", "rosgraph_msgs/Log")
    reply = rospy.ServiceProxy("/static_map", GetMap)()
    assert reply.map.info.width > 0 and reply.map.header.stamp == reply.map.info.map_load_time
    now = nav.now()
    line = nav.wait_for_message("/rosout_agg", 10, predicate=lambda msg: msg["msg"] == "Sending map")
    assert line["name"] == "/map_server" and abs(line["header"]["stamp"] - now) < 1.0
    wait_until(lambda: not _map_server_follows_the_clock(ros_master.uri), 10, "map_server leaving /clock")


def test_a_zero_quaternion_is_aborted_at_once(nav):
    status, text, waited = wait_result(nav, send_goal(nav, 1.0, 0.5, quaternion=(0, 0, 0, 0)), 10)
    assert (status, text) == (ABORTED, "Aborting on goal because it was sent with an invalid quaternion")
    assert waited < 1.0


@pytest.mark.parametrize("zone", list(part3.ZONES))
def test_rostopic_pub_goal_reaches_the_zone(ros_master, nav, zone):
    result = part3.go_to_zone(ros_master, nav, zone)
    assert result["text"] == "Goal reached." and part3.reached(result), result


def test_a_goal_inside_a_wall_is_aborted_after_the_recoveries(nav):
    status, text, waited = wait_result(nav, send_goal(nav, *INSIDE_WALL_4), 120)
    assert (status, text) == (ABORTED, "Failed to find a valid plan. Even after executing recovery behaviors.")
    assert waited >= 5 * 5.0   # planner_patience before each recovery and after the last


def test_a_new_goal_preempts_and_cancel_stops_the_robot(nav):
    first = send_goal(nav, 0.9, -0.6)
    nav.sleep_sim(3.0, 60)
    second = send_goal(nav, -0.6, 0.3)
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


def test_a_new_particlecloud_subscriber_gets_the_latched_cloud_once(nav):
    """The robot stands (the cancel above), so amcl sends no new cloud: a subscriber that comes now gets the last
    one, latched, exactly once (the original publishes it latched on each filter update)."""
    nav.subscribe("/particlecloud", "geometry_msgs/PoseArray")
    nav.sleep_sim(2.0, 60)
    clouds = [entry["msg"] for entry in nav.take("/particlecloud")]
    assert len(clouds) == 1
    assert clouds[0]["header"]["frame_id"] == "map" and 500 <= len(clouds[0]["poses"]) <= 3000
