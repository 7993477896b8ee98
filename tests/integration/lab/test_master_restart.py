"""roscore restarted under a running demo: the Week 4 servers, the simulator and turtlesim re-register with
the new master (master_reconnect), and a service call from a new client works again within 10 s."""
import subprocess
import time

import pytest

from roslab import wait_for_service, wait_for_topic, wait_until

RECOVER_WITHIN_S = 10.0


@pytest.fixture(scope="module")
def demo(ros_master):
    ros_master.roslaunch("week4_services", "week4_demo.launch", "gui:=false", "real_time_factor:=2")
    ros_master.rosrun("turtlesim", "turtlesim_node", "_headless:=true")
    wait_for_service(ros_master.uri, "/timed_move_service", timeout_s=60)
    wait_for_service(ros_master.uri, "/spawn")
    wait_for_topic(ros_master.uri, "/odom")
    return ros_master


def call_succeeds(master, service="/timed_move_service", request="{movement_request: 'left', duration: 1}",
                  expected="success: True"):
    result = subprocess.run(["rosservice", "call", service, request], env=master.env, stdout=subprocess.PIPE,
                            stderr=subprocess.STDOUT, text=True, timeout=30)
    return result.returncode == 0 and expected in result.stdout


def test_service_call_works_again_within_10_s_of_a_roscore_restart(demo):
    assert call_succeeds(demo)
    demo.restart_core()
    restarted = time.monotonic()
    wait_until(lambda: call_succeeds(demo), RECOVER_WITHIN_S, "a /timed_move_service call after the restart",
               interval_s=0.5)
    assert time.monotonic() - restarted < RECOVER_WITHIN_S


def test_a_new_subscriber_gets_odom_after_the_restart(demo):
    wait_for_topic(demo.uri, "/odom", timeout_s=RECOVER_WITHIN_S)
    probe = demo.probe()
    probe.subscribe("/odom", "nav_msgs/Odometry")
    assert probe.wait_for_message("/odom", timeout_s=RECOVER_WITHIN_S)["child_frame_id"] == "base_footprint"


def test_turtlesim_serves_again_after_the_restart(demo):
    wait_until(lambda: call_succeeds(demo, "/spawn", "{x: 2.0, y: 2.0, theta: 0.0, name: ''}", "name: \"turtle2\""),
               RECOVER_WITHIN_S, "a /spawn call after the restart", interval_s=0.5)
