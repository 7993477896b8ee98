"""Calibration: the grader agrees with a marker who follows the Week 4 page. Graded in one run (2 at a time, the
simulator at 2x): the lab's reference solution, and a package written in the course template's habits
(student_style/week4_course_template) - whole-second timing (`rospy.get_rostime().secs`), publishers at module
level, bare return values (a tuple for SetBool, a bool, a string), the older message packages (tuos_ros_msgs,
com2009_msgs), its own file names (timed_server.py, approach_object_server.py) and Parts 1 and 2 both on
/move_service. A marker gives both full marks; the grader's verdicts, check by check, are stated below."""
import json
import os
import time

import pytest

from .sample_submissions import make_submission
from .test_grade_class import grade, results, verdicts

REAL_TIME_FACTOR = "2"
REQUIRED = ("move_true", "move_false", "timed_fwd", "timed_back", "timed_left", "timed_right", "timed_invalid_word",
            "timed_zero_duration", "timed_negative_duration", "approach_stops_at_distance")
ADVICE = ("approach_velocity_too_fast", "approach_velocity_zero", "approach_velocity_negative",
          "approach_velocity_nan", "approach_distance_too_close", "approach_distance_out_of_range",
          "approach_distance_nan")


@pytest.fixture(scope="module")
def graded(ros_master, tmp_path_factory):
    folder = tmp_path_factory.mktemp("calibration")
    for name in ("reference", "course_template"):
        make_submission(name, folder)
    out = tmp_path_factory.mktemp("calibration_grades")
    started = time.monotonic()
    grade(dict(os.environ), folder, "--suite", "week4", "--out", out, "--jobs", "2", "--rtf", REAL_TIME_FACTOR)
    print("calibration grade run: {:.0f} s".format(time.monotonic() - started))
    return results(out)


def by_id(result):
    return {check["id"]: check for check in result["checks"]}


@pytest.mark.slow
def test_the_reference_passes_every_check_required_and_advice(graded):
    result = graded["reference"]
    assert set(verdicts(result).values()) == {"pass"}, json.dumps(result["checks"], indent=1)[:3000]
    assert result["score"] == result["max_score"] == 100
    assert {check["id"]: check["kind"] for check in result["checks"]} == dict(
        [(check_id, "required") for check_id in REQUIRED] + [(check_id, "advice") for check_id in ADVICE])


@pytest.mark.slow
def test_the_course_templates_habits_get_full_marks(graded):
    result = graded["course_template"]
    checks = by_id(result)
    # Every required check passes: whole-second timing (a 5 s move lasting 4..5 s, a 2 s one 1..2 s) is in the
    # tolerance; the tuple, the bool and the string rospy turns into responses; the old message packages' types
    # have the same md5sums.
    assert {check_id: checks[check_id]["verdict"] for check_id in REQUIRED} == dict.fromkeys(REQUIRED, "pass"), \
        json.dumps([checks[check_id] for check_id in REQUIRED], indent=1)[:3000]
    assert result["score"] == result["max_score"] == 100
    move = checks["move_true"]["evidence"]["motion"]
    assert 3.9 < move["duration_s"] <= 5.5 and 0.35 <= move["forward_m"] <= 0.6, move
    # The speed above the Waffle's maximum is taken (the template does not check it): an advice failure, 0 points.
    assert checks["approach_velocity_too_fast"]["verdict"] == "fail"
    assert "expected to stay within 0.01 m" in checks["approach_velocity_too_fast"]["reason"]
    assert {check_id: checks[check_id]["verdict"] for check_id in ADVICE if check_id != "approach_velocity_too_fast"} \
        == dict.fromkeys(set(ADVICE) - {"approach_velocity_too_fast"}, "pass")


@pytest.mark.slow
def test_other_file_names_and_one_service_name_for_two_parts_are_found_as_a_marker_would(graded):
    result = graded["course_template"]
    nodes = {node["exercise"]: node for node in result["nodes"]}
    assert nodes["move_server.py"]["found_by"] == "the course's file name"
    assert nodes["timed_move_server.py"]["file"] == "week4_course_template/src/timed_server.py"
    assert nodes["approach_server.py"]["file"] == "week4_course_template/src/approach_object_server.py"
    assert {nodes[name]["found_by"] for name in ("timed_move_server.py", "approach_server.py")} == {
        "found by trying each script"}
    services = result["services"]
    assert services["/move_service"]["found_type"] == "tuos_ros_msgs/SetBool"
    # Part 2 serves on /move_service too: alone (as the page shows it), it is found there by type
    assert services["/timed_move_service"]["found"] == "/move_service"
    assert services["/timed_move_service"]["found_by"] == "by type"
    assert services["/timed_move_service"]["found_type"] == "com2009_msgs/TimedMovement"
    assert services["/approach_service"]["found_type"] == "com2009_msgs/Approach"
