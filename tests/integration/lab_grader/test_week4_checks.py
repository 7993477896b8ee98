"""`rosrun lab_grader run_checks --suite week4` against tb3_sim in the approach arena, as the grader runs it.

First the lab's reference servers (roslaunch week4_services week4_demo.launch): every check passes, full score,
every service found by name. Then, on the same master and simulator, the reference servers are replaced by
deliberately wrong student-like nodes written here (never in the repository): a /move_service that drives
backwards, a /timed_move_service whose callback never returns, and an approach service under another name
(/my_approach) and another package's type (com2009_msgs/Approach): the move check fails naming the direction,
the timed checks are errors "no reply within", and the approach service is found by type.

Not marked realtime: the checks judge in sim time, and the reference approach pairs its sweeps with odometry by
stamp. test_grade_class grades the same reference servers with the same checks at the same factor beside the rest
of the suite in every run, and gives them full marks.
"""
import json
import subprocess
import sys
import textwrap
import time

import pytest

from roslab import stop_together, wait_for_service, wait_for_service_gone

pytestmark = pytest.mark.slow

REAL_TIME_FACTOR = "2"
REFERENCE_SERVERS = ("/move_service_server", "/timed_move_service_server", "/approach_service_server")
COURSE_SERVICES = ("/move_service", "/timed_move_service", "/approach_service")
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
def reference(ros_master):
    """tb3_sim in the approach arena and the three reference servers."""
    ros_master.roslaunch("week4_services", "week4_demo.launch", "gui:=false",
                         "real_time_factor:=" + REAL_TIME_FACTOR)
    for name in COURSE_SERVICES + ("/gazebo/reset_world",):
        wait_for_service(ros_master.uri, name, timeout_s=60)
    return ros_master


def run_checks(ros_master, out, *extra):
    """Run the grader's check runner; returns (results, its output, wall seconds)."""
    started = time.monotonic()
    finished = subprocess.run(["rosrun", "lab_grader", "run_checks", "--suite", "week4", "--out", str(out), *extra],
                              env=ros_master.env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                              timeout=RUN_TIMEOUT_WALL_S)
    elapsed = time.monotonic() - started
    assert finished.returncode == 0, finished.stdout
    return json.loads(out.read_text()), finished.stdout, elapsed


def by_id(results):
    return {check["id"]: check for check in results["checks"]}


def test_the_reference_servers_pass_every_check(reference, tmp_path):
    results, output, elapsed = run_checks(reference, tmp_path / "r.json")
    print("reference run: {:.1f} s wall, {} s sim".format(elapsed, results["timing"].get("sim_s")))
    failed = [(c["id"], c["verdict"], c["reason"]) for c in results["checks"] if c["verdict"] != "pass"]
    assert failed == [], output
    assert results["suite"] == "week4" and results["complete"] is True
    assert results["score"] == results["max_score"] == 100
    assert len(results["checks"]) == 17
    for name in COURSE_SERVICES:
        assert results["services"][name]["found"] == name
        assert results["services"][name]["found_by"] == "by name"
    checks = by_id(results)
    move = checks["move_true"]["evidence"]
    assert move["reply"]["response_signal"] is True
    assert move["motion"]["forward_m"] == pytest.approx(0.5, abs=0.03)
    assert move["motion"]["duration_s"] == pytest.approx(5.0, abs=0.3)
    assert 10 < len(move["trajectory"]) <= 400
    assert checks["approach_stops_at_distance"]["evidence"]["front_distance_m"] == pytest.approx(0.4, abs=0.05)
    assert checks["approach_distance_nan"]["evidence"]["request"]["approach_distance"] == "nan"


@pytest.fixture
def wrong_servers(reference, tmp_path):
    """The reference servers stopped; the wrong ones started with the venv's python against the same master and
    simulator, and stopped at the end (the fixture's teardown, even when the test fails)."""
    subprocess.run(["rosnode", "kill", *REFERENCE_SERVERS], env=reference.env, check=True, timeout=30,
                   stdout=subprocess.DEVNULL, stderr=subprocess.STDOUT)
    for name in COURSE_SERVICES:
        wait_for_service_gone(reference.uri, name, timeout_s=30)
    processes = []
    for label, code in (("backwards_move_server", BACKWARDS_MOVE_SERVER),
                        ("hung_timed_move_server", NEVER_REPLYING_TIMED_SERVER),
                        ("my_approach_server", RENAMED_APPROACH_SERVER)):
        script = tmp_path / (label + ".py")
        script.write_text(textwrap.dedent(code))
        processes.append(reference.start([sys.executable, str(script)], label))
    try:
        for name in ("/move_service", "/timed_move_service", "/my_approach"):
            wait_for_service(reference.uri, name, timeout_s=30)
        yield reference
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
    assert results["score"] == 6 + 7 * 2 and results["max_score"] == 100 and results["complete"] is True
