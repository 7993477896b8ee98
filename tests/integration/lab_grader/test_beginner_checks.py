"""The beginner_tutorials suite (add_two_int and the counter action; no simulator, only roscore).

First the whole grader (`rosrun lab_grader grade --suite beginner_tutorials`) on a copy of the lab's own package,
built and run in its sandbox: full marks, the service and the action found by name, with the evidence of each
check. Then `rosrun lab_grader run_checks`, as the grader runs it, against student-like nodes written here (never
in the repository) under their own names: an add_two_int server that adds as floats (exact for small numbers,
wrong at the int64 edges) and a counter server that counts from 1 and ignores cancels. Both are found by type; the
int64 and feedback checks fail naming what happened.

Marked realtime: the counter's one count per second and its preemption are judged in ROS time, which is wall time
without a simulator.
"""
import json
import os
import shutil
import subprocess
import sys
import textwrap

import pytest

from roslab import stop_together, wait_for_service

from .conftest import LAB_ROOT

pytestmark = [pytest.mark.realtime, pytest.mark.slow]

RUN_TIMEOUT_WALL_S = 120

FLOAT_ADD_SERVER = """
import rospy
from beginner_tutorials.srv import add_two_int, add_two_intResponse


def add(request):
    return add_two_intResponse(int(float(request.a) + float(request.b)))   # the mistake: floats lose int64 digits


rospy.init_node("my_adder")
rospy.Service("/my_adder/add", add_two_int, add)
rospy.spin()
"""

STUBBORN_COUNTER_SERVER = """
import actionlib
import rospy
from beginner_tutorials.msg import counterAction, counterFeedback, counterResult


def execute(goal):
    rate = rospy.Rate(1)
    for count in range(1, goal.num_counts + 1):        # the mistakes: counts from 1, never looks at a cancel
        server.publish_feedback(counterFeedback(counts_elapsed=count))
        rate.sleep()
    server.set_succeeded(counterResult(result_message="done"))


rospy.init_node("my_counter")
server = actionlib.SimpleActionServer("/counter", counterAction, execute_cb=execute, auto_start=False)
server.start()
rospy.spin()
"""


def run_checks(ros_master, out):
    finished = subprocess.run(["rosrun", "lab_grader", "run_checks", "--suite", "beginner_tutorials", "--out",
                               str(out)], env=ros_master.env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                              text=True, timeout=RUN_TIMEOUT_WALL_S)
    assert finished.returncode == 0, finished.stdout
    results = json.loads(out.read_text())
    return results, {check["id"]: check for check in results["checks"]}, finished.stdout


@pytest.fixture
def student_nodes(ros_master, tmp_path):
    processes = []
    for label, code in (("my_adder", FLOAT_ADD_SERVER), ("my_counter", STUBBORN_COUNTER_SERVER)):
        script = tmp_path / (label + ".py")
        script.write_text(textwrap.dedent(code))
        processes.append(ros_master.start([sys.executable, str(script)], label))
    try:
        wait_for_service(ros_master.uri, "/my_adder/add", timeout_s=30)
        yield ros_master
    finally:
        stop_together(processes)


def test_float_sums_and_a_counter_that_ignores_cancels_fail_with_reasons(student_nodes, tmp_path):
    results, checks, output = run_checks(student_nodes, tmp_path / "r.json")
    assert results["services"]["/add_two_int"]["found"] == "/my_adder/add"
    assert results["services"]["/add_two_int"]["found_by"] == "by type"
    assert results["services"]["/my_action_server"]["found"] == "/counter"
    assert results["services"]["/my_action_server"]["found_by"] == "by type"
    verdicts = {check_id: check["verdict"] for check_id, check in checks.items()}
    assert verdicts == {"add_small": "pass", "add_negative": "pass", "add_int64_max": "error",
                        "add_int64_min": "pass", "add_int64_extremes": "fail", "add_overflow_refused": "pass",
                        "add_after_overflow": "pass", "count_three": "fail", "count_cancelled": "fail",
                        "count_zero_ends": "pass"}, output
    assert "expected sum -1, it replied 0" in checks["add_int64_extremes"]["reason"]
    assert "expected feedback counts_elapsed [0, 1, 2], it sent [1, 2, 3]" in checks["count_three"]["reason"]
    assert "expected the goal to end PREEMPTED, it ended SUCCEEDED" in checks["count_cancelled"]["reason"]
    assert results["score"] == 10 + 5 + 5 + 5 + 10 + 5


def test_the_labs_own_package_scores_full_marks_in_the_grader(tmp_path):
    student = tmp_path / "class" / "lab_reference"
    shutil.copytree(LAB_ROOT / "catkin_ws/src/exercises/beginner_tutorials", student / "beginner_tutorials",
                    ignore=shutil.ignore_patterns("__pycache__", "*.pyc"))
    run = subprocess.run(["rosrun", "lab_grader", "grade", str(tmp_path / "class"), "--suite", "beginner_tutorials",
                          "--out", str(tmp_path / "out"), "-j", "1"], env=dict(os.environ), capture_output=True,
                         text=True, timeout=300)
    assert run.returncode == 0, run.stdout + run.stderr
    results = json.loads((tmp_path / "out" / "lab_reference" / "result.json").read_text())
    failed = [(c["id"], c["verdict"], c["reason"]) for c in results["checks"] if c["verdict"] != "pass"]
    assert failed == [] and results["problems"] == [], json.dumps(results, indent=1)[:3000]
    assert results["score"] == results["max_score"] == 100 and len(results["checks"]) == 10
    assert not (tmp_path / "out" / "lab_reference" / "simulator.log").exists()
    for name in ("/add_two_int", "/my_action_server"):
        assert results["services"][name]["found"] == name and results["services"][name]["found_by"] == "by name"
    checks = {check["id"]: check for check in results["checks"]}
    assert checks["add_int64_max"]["evidence"]["reply"] == {"sum": 9223372036854775807}
    assert "int64 range" in checks["add_overflow_refused"]["evidence"]["server_error"]
    count = checks["count_three"]["evidence"]
    assert [fields["counts_elapsed"] for _, fields in count["feedback"]] == [0, 1, 2]
    assert count["state"] == "SUCCEEDED" and count["result"] == {"result_message": "Counting complete!"}
    assert count["ended_after_s"] == pytest.approx(3.0, abs=0.5)
    cancelled = checks["count_cancelled"]["evidence"]
    assert cancelled["state"] == "PREEMPTED" and cancelled["cancelled_after_s"] == pytest.approx(2.5, abs=0.2)
    assert "after 3 of 10 counts" in cancelled["result"]["result_message"]
    assert checks["count_zero_ends"]["evidence"]["state"] == "ABORTED"
