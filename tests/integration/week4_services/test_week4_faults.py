"""Faults under the Week 4 demo: a simulator that dies or is reset mid-request gets a failure reply within 2 s
instead of a hang; roslaunch respawns it and the servers serve again; a client killed mid-call wedges nothing.
The tests share one launch: a test that kills the simulator leaves the next one a respawned simulator, and the next
test starts once the servers serve again on it, as the respawn test proves they do."""
import os
import signal
import time

import pytest
import rosgraph
import rospy
from std_srvs.srv import Empty
from tuos_msgs.srv import Approach, TimedMovement

from roslab import wait_for_service, wait_for_topic, wait_until
from roslab.calls import BackgroundCall
from roslab.graph import node_pid
from roslab.robot_view import RobotView

ANSWER_WITHIN_S = 2.0


@pytest.fixture(scope="module")
def week4_launch(ros_master):
    """The Week 4 demo launch for the module's tests, with the simulator's pid (a list: the respawned one's later)."""
    launch = ros_master.roslaunch("week4_services", "week4_demo.launch", "gui:=false", "real_time_factor:=1")
    for name in ["/approach_service", "/timed_move_service"]:
        wait_for_service(ros_master.uri, name, timeout_s=60)
    wait_for_topic(ros_master.uri, "/odom")
    yield [node_pid(ros_master.uri, "/gazebo")]
    launch.stop()


@pytest.fixture
def week4(ros_master, week4_launch):
    """The module's Week 4 demo, its servers serving: after a test that killed the simulator, once a timed move
    (a 1 s turn in place) succeeds on the respawned one."""
    simulator_pid = week4_launch
    if alive_pid(ros_master.uri) == simulator_pid[0]:
        return ros_master
    wait_until(lambda: respawned(ros_master.uri, simulator_pid[0]), 30, "roslaunch to respawn the simulator")
    call = rospy.ServiceProxy("/timed_move_service", TimedMovement)
    wait_until(lambda: call("left", 1).success, 30, "a successful timed move on the respawned simulator",
               interval_s=0.5)
    simulator_pid[0] = node_pid(ros_master.uri, "/gazebo")
    return ros_master


def fault_during(fault, name, srv_type, *args):
    """Call the service, inject `fault` (a function) 2 s into the call; (reply, seconds from fault to reply)."""
    call = BackgroundCall(name, srv_type, *args)
    time.sleep(2.0)
    assert call.running(), "the call ended before the fault: {}".format(call)
    fault()
    faulted_at = time.monotonic()
    assert call.join(timeout_s=10), "the call is still hanging 10 s after the fault"
    return call.reply, call.answered_at - faulted_at


def kill_simulator_during(week4, name, srv_type, *args):
    return fault_during(lambda: os.kill(node_pid(week4.uri, "/gazebo"), signal.SIGKILL), name, srv_type, *args)


def test_approach_fails_within_2_s_when_the_simulator_dies(week4):
    reply, answered_after = kill_simulator_during(week4, "/approach_service", Approach, 0.4, 0.05)
    assert answered_after < ANSWER_WITHIN_S
    # the watchdog notices first either the silence (no /odom for 1 s) or, when roslaunch respawns the
    # simulator sooner, its clock starting again from 0
    assert reply.response_message.startswith("Request failed: ")
    assert ("is the simulator running?" in reply.response_message
            or "the simulator restarted" in reply.response_message), reply.response_message


def test_timed_move_fails_within_2_s_when_the_simulator_dies(week4):
    reply, answered_after = kill_simulator_during(week4, "/timed_move_service", TimedMovement, "fwd", 10)
    assert answered_after < ANSWER_WITHIN_S
    assert reply.success is False


def test_timed_move_fails_within_2_s_when_the_simulation_is_reset(week4, probe):
    """/gazebo/reset_simulation rewinds the clock: a duration measured on the old clock is meaningless, so the
    request fails at once (rospy.sleep would raise ROSTimeMovedBackwardsException) and the robot stays put."""
    robot = RobotView(probe)
    reset = rospy.ServiceProxy("/gazebo/reset_simulation", Empty)
    reply, answered_after = fault_during(reset, "/timed_move_service", TimedMovement, "fwd", 10)
    assert answered_after < ANSWER_WITHIN_S
    assert reply.success is False
    x, y, _ = robot.settled_pose()
    time.sleep(1.0)
    assert robot.pose()[:2] == pytest.approx((x, y), abs=0.005), "the robot kept moving after the failure"


def test_the_respawned_simulator_is_served_again(week4):
    killed_pid = node_pid(week4.uri, "/gazebo")
    os.kill(killed_pid, signal.SIGKILL)
    wait_until(lambda: respawned(week4.uri, killed_pid), 30, "roslaunch to respawn the simulator")
    call = rospy.ServiceProxy("/timed_move_service", TimedMovement)
    wait_until(lambda: call("left", 1).success, 30, "a successful timed move on the respawned simulator",
               interval_s=0.5)


def alive_pid(master_uri):
    """The simulator's pid, or None while it is dead (the master keeps a dead node's URI until it respawns)."""
    try:
        return node_pid(master_uri, "/gazebo")
    except (OSError, rosgraph.MasterError):
        return None


def respawned(master_uri, old_pid):
    """True once /gazebo answers from a process other than `old_pid`."""
    return alive_pid(master_uri) not in (None, old_pid)


def test_a_client_killed_mid_call_does_not_wedge_the_server(week4):
    client = week4.start(["rosservice", "call", "/timed_move_service", "{movement_request: 'fwd', duration: 3}"],
                         "doomed_client")
    time.sleep(1.5)
    assert client.running()
    client.signal(signal.SIGKILL)
    killed_at = time.monotonic()
    call = rospy.ServiceProxy("/timed_move_service", TimedMovement)
    while not call("left", 1).success:   # refused while the killed client's motion finishes, then served
        assert time.monotonic() - killed_at < 10.0, "the server never served again after its client died"
        time.sleep(0.2)
