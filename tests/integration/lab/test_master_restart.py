"""roscore restarted under a running demo: the Week 4 servers, the simulator and turtlesim re-register with
the new master (master_reconnect), each saying so once, and a service call from a new client works again within
10 s. Before the restart none of them claims a re-registration."""
import subprocess
import time

import pytest

from master_reconnect.watchdog import CHECK_PERIOD_WALL_S
from roslab import wait_for_service, wait_for_topic, wait_until

RECOVER_WITHIN_S = 10.0


REREGISTERED = "re-registered with a restarted ROS master"
WATCHED_NODES_IN_LAUNCH = 4   # tb3_sim and the three Week 4 servers


@pytest.fixture(scope="module")
def launch(ros_master):
    """The Week 4 demo launch (its nodes print to its output), with a turtlesim beside it."""
    process = ros_master.roslaunch("week4_services", "week4_demo.launch", "gui:=false", "real_time_factor:=2")
    ros_master.rosrun("turtlesim", "turtlesim_node", "_headless:=true")
    wait_for_service(ros_master.uri, "/timed_move_service", timeout_s=60)
    wait_for_service(ros_master.uri, "/spawn")
    wait_for_topic(ros_master.uri, "/odom")
    return process


@pytest.fixture(scope="module")
def demo(ros_master, launch):
    return ros_master


def call_succeeds(master, service="/timed_move_service", request="{movement_request: 'left', duration: 1}",
                  expected="success: True"):
    result = subprocess.run(["rosservice", "call", service, request], env=master.env, stdout=subprocess.PIPE,
                            stderr=subprocess.STDOUT, text=True, timeout=30)
    return result.returncode == 0 and expected in result.stdout


def test_service_call_works_again_within_10_s_of_a_roscore_restart(demo, launch):
    assert call_succeeds(demo)
    time.sleep(2 * CHECK_PERIOD_WALL_S)   # the watchdogs have looked at the master meanwhile
    assert REREGISTERED not in launch.output()
    demo.restart_core()
    restarted = time.monotonic()
    wait_until(lambda: call_succeeds(demo), RECOVER_WITHIN_S, "a /timed_move_service call after the restart",
               interval_s=0.5)
    assert time.monotonic() - restarted < RECOVER_WITHIN_S
    wait_until(lambda: launch.output().count(REREGISTERED) >= WATCHED_NODES_IN_LAUNCH, RECOVER_WITHIN_S,
               "every watched node of the launch to say it re-registered")
    time.sleep(2 * CHECK_PERIOD_WALL_S)
    assert launch.output().count(REREGISTERED) == WATCHED_NODES_IN_LAUNCH, "once each"


def test_a_new_subscriber_gets_odom_after_the_restart(demo):
    wait_for_topic(demo.uri, "/odom", timeout_s=RECOVER_WITHIN_S)
    probe = demo.probe()
    probe.subscribe("/odom", "nav_msgs/Odometry")
    assert probe.wait_for_message("/odom", timeout_s=RECOVER_WITHIN_S)["child_frame_id"] == "base_footprint"


def test_turtlesim_serves_again_after_the_restart(demo):
    wait_until(lambda: call_succeeds(demo, "/spawn", "{x: 2.0, y: 2.0, theta: 0.0, name: ''}", "name: \"turtle2\""),
               RECOVER_WITHIN_S, "a /spawn call after the restart", interval_s=0.5)
