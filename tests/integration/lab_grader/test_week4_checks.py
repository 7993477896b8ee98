"""`rosrun lab_grader run_checks --suite week4` against tb3_sim in the approach arena, as the grader runs it, and
deliberately wrong student-like nodes written here (never in the repository): a /move_service that drives
backwards, a /timed_move_service whose callback never returns, and an approach service under another name
(/my_approach) and another package's type (com2009_msgs/Approach): the move check fails naming the direction,
the timed checks are errors "no reply within", and the approach service is found by type. Then, on the same master
and simulator, a move server that fakes its own motion (pauses physics, publishes its own /clock and /odom of a
0.5 m drive, replies True, unpauses) gets "interference" naming what it did, while its honest reply to False still
passes.

The reference servers' full marks with these checks, and their evidence (the 0.5 m move, the approach's stop at
0.4 m), are test_grade_class's: it grades the same servers with the same checks at the same factor, so they are
not run here a second time (that run was 17 checks, 35 s of this module's 102 s at load 7-9).

Not marked realtime: the checks judge in sim time.
"""
import json
import shutil
import subprocess
import sys
import tempfile
import textwrap
import time
from pathlib import Path

import pytest

from roslab import stop_together, wait_for_service

from .test_grade_hostile import move_service_suite as move_only_suite

pytestmark = pytest.mark.slow

REAL_TIME_FACTOR = "2"
RUN_TIMEOUT_WALL_S = 240
WRONG_SERVER_CHECK_TIMEOUT_S = "3"     # sim s: keeps the seven hung timed checks short

BACKWARDS_MOVE_SERVER = """
import rospy
from geometry_msgs.msg import Twist
from tuos_msgs.srv import SetBool, SetBoolResponse

rospy.init_node("backwards_move_server")
cmd_vel = rospy.Publisher("/cmd_vel", Twist, queue_size=1)


def callback(request):
    if not request.request_signal:
        return SetBoolResponse(False, "Send true to move.")
    twist = Twist()
    twist.linear.x = -0.2          # the mistake: backwards (and for 2 s, so the run's timeout can be short)
    cmd_vel.publish(twist)
    rospy.sleep(2.0)
    cmd_vel.publish(Twist())
    return SetBoolResponse(True, "Moved.")


rospy.Service("/move_service", SetBool, callback)
rospy.spin()
"""

NEVER_REPLYING_TIMED_SERVER = """
import time

import rospy
from tuos_msgs.srv import TimedMovement


def callback(request):
    while not rospy.is_shutdown():     # the mistake: it never returns
        time.sleep(0.1)


rospy.init_node("hung_timed_move_server")
rospy.Service("/timed_move_service", TimedMovement, callback)
rospy.spin()
"""

RENAMED_APPROACH_SERVER = """
import rospy
from com2009_msgs.srv import Approach, ApproachResponse


def callback(request):
    return ApproachResponse("Not implemented yet.")


rospy.init_node("my_approach_server")
rospy.Service("/my_approach", Approach, callback)
rospy.spin()
"""


@pytest.fixture(scope="module")
def simulator(ros_master):
    """tb3_sim in the approach arena, serving its ground truth on a private socket. The socket's path is short (a
    Unix socket path has at most 107 bytes): a folder of its own in /tmp."""
    folder = Path(tempfile.mkdtemp(prefix="truth-", dir="/tmp"))
    ros_master.truth_socket = folder / "truth.sock"
    ros_master.roslaunch("tb3_sim", "tb3_sim.launch", "world:=approach_arena", "gui:=false",
                         "real_time_factor:=" + REAL_TIME_FACTOR, "ground_truth_socket:={}".format(
                             ros_master.truth_socket))
    wait_for_service(ros_master.uri, "/gazebo/reset_world", timeout_s=60)
    yield ros_master
    shutil.rmtree(folder, ignore_errors=True)


def run_checks(ros_master, out, *extra, suite="week4"):
    """Run the grader's check runner; returns (results, its output, wall seconds)."""
    started = time.monotonic()
    finished = subprocess.run(["rosrun", "lab_grader", "run_checks", "--suite", str(suite), "--out", str(out),
                               "--ground-truth", str(ros_master.truth_socket), *extra],
                              env=ros_master.env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                              timeout=RUN_TIMEOUT_WALL_S)
    elapsed = time.monotonic() - started
    assert finished.returncode == 0, finished.stdout
    return json.loads(out.read_text()), finished.stdout, elapsed


def by_id(results):
    return {check["id"]: check for check in results["checks"]}


def start_scripts(ros_master, folder, scripts, services):
    """Start each (label, code) of `scripts` with the venv's python; wait for `services`; returns the processes."""
    processes = []
    for label, code in scripts:
        script = folder / (label + ".py")
        script.write_text(textwrap.dedent(code))
        processes.append(ros_master.start([sys.executable, str(script)], label))
    for name in services:
        wait_for_service(ros_master.uri, name, timeout_s=30)
    return processes


@pytest.fixture
def wrong_servers(simulator, tmp_path):
    """The wrong servers started against the same master and simulator, and stopped at the end (the fixture's
    teardown, even when the test fails)."""
    processes = start_scripts(simulator, tmp_path, (("backwards_move_server", BACKWARDS_MOVE_SERVER),
                                                            ("hung_timed_move_server", NEVER_REPLYING_TIMED_SERVER),
                                                            ("my_approach_server", RENAMED_APPROACH_SERVER)),
                              ("/move_service", "/timed_move_service", "/my_approach"))
    try:
        yield simulator
    finally:
        stop_together(processes)


def test_wrong_servers_fail_error_and_are_found_by_type(wrong_servers, tmp_path):
    results, output, elapsed = run_checks(wrong_servers, tmp_path / "r.json",
                                          "--check-timeout", WRONG_SERVER_CHECK_TIMEOUT_S)
    print("wrong-servers run: {:.1f} s wall".format(elapsed))
    checks = by_id(results)
    move = checks["move_true"]
    assert move["verdict"] == "fail", output
    assert "drove backwards" in move["reason"] and "expected to drive forwards" in move["reason"]
    assert move["evidence"]["motion"]["forward_m"] == pytest.approx(-0.4, abs=0.05)
    assert checks["move_false"]["verdict"] == "pass", checks["move_false"]["reason"]

    timed = [check for check in results["checks"] if check["id"].startswith("timed_")]
    assert len(timed) == 7
    for check in timed:
        assert check["verdict"] == "error", check
        assert check["reason"].startswith("no reply within 3 s"), check["reason"]
        assert check["evidence"]["reply"] is None

    approach = results["services"]["/approach_service"]
    assert approach["found"] == "/my_approach" and approach["found_by"] == "by type"
    assert approach["found_type"] == "com2009_msgs/Approach"
    assert results["services"]["/move_service"]["found_by"] == "by name"
    assert checks["approach_stops_at_distance"]["verdict"] == "fail"
    assert checks["approach_stops_at_distance"]["evidence"]["reply"] == {"response_message": "Not implemented yet."}
    refusals = [check for check in results["checks"] if check["id"].startswith("approach_")
                and check["id"] != "approach_stops_at_distance"]
    assert [check["verdict"] for check in refusals] == ["pass"] * 7
    assert {check["kind"] for check in refusals} == {"advice"}, "validation the Week 4 page does not ask for"
    assert results["score"] == 6 and results["max_score"] == 100 and results["complete"] is True


FAKING_MOVE_SERVER = """
import time

import rospy
from nav_msgs.msg import Odometry
from rosgraph_msgs.msg import Clock
from std_srvs.srv import Empty
from tuos_msgs.srv import SetBool, SetBoolResponse

rospy.init_node("faking_move_server")
clock = rospy.Publisher("/clock", Clock, queue_size=10)
odom = rospy.Publisher("/odom", Odometry, queue_size=10)
pause = rospy.ServiceProxy("/gazebo/pause_physics", Empty)
unpause = rospy.ServiceProxy("/gazebo/unpause_physics", Empty)


def callback(request):
    if not request.request_signal:
        return SetBoolResponse(False, "Send true to move.")
    pause()
    start = rospy.get_rostime()
    for step in range(51):     # 5 s of a 0.1 m/s drive, in its own clock, while the real one stands still
        now = start + rospy.Duration(0.1 * step)
        clock.publish(Clock(clock=now))
        fake = Odometry()
        fake.header.stamp = now
        fake.pose.pose.position.x = 0.01 * step
        fake.pose.pose.orientation.w = 1.0
        fake.twist.twist.linear.x = 0.1 if step < 50 else 0.0
        odom.publish(fake)
        time.sleep(0.02)
    unpause()
    return SetBoolResponse(True, "Request complete: the robot moved forwards for 5.0 seconds.")


rospy.Service("/move_service", SetBool, callback)
rospy.spin()
"""


def test_a_server_that_fakes_its_motion_gets_interference_and_its_honest_reply_passes(simulator, tmp_path):
    suite = move_only_suite(tmp_path / "move_only.yaml")
    processes = start_scripts(simulator, tmp_path, (("faking_move_server", FAKING_MOVE_SERVER),),
                              ("/move_service",))
    try:
        results, output, elapsed = run_checks(simulator, tmp_path / "r.json", suite=suite)
    finally:
        stop_together(processes)
    print("faking-server run: {:.1f} s wall".format(elapsed))
    checks = by_id(results)
    move = checks["move_true"]
    assert move["verdict"] == "interference", output
    for what in ("physics was paused", "called /gazebo/pause_physics", "called /gazebo/unpause_physics",
                 "published /clock (node /faking_move_server)", "published /odom (node /faking_move_server)"):
        assert what in move["reason"], move["reason"]
    assert abs(move["evidence"]["motion"]["forward_m"]) < 0.01, "the robot never moved: the truth says so"
    assert checks["move_false"]["verdict"] == "pass", checks["move_false"]["reason"]
    assert results["score"] == 6
