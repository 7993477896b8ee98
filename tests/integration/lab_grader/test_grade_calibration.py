"""Calibration: the grader agrees with a marker who follows the Week 4 page. A package written in the course
template's habits (student_style/week4_course_template) - whole-second timing (`rospy.get_rostime().secs`),
publishers at module level, bare return values (a tuple for SetBool, a bool, a string), the older message packages
(tuos_ros_msgs, com2009_msgs), its own file names (timed_server.py, approach_object_server.py) and Parts 1 and 2
both on /move_service - gets full marks, as a marker gives it (the lab's reference is graded in
test_grade_class.py); and copies of the reference with mistakes a marker judges by name or by the input a server
takes (services under the student's own names, a timed move that accepts anything, a robot never stopped) get the
verdicts those deserve, graded in one run with the template."""
import json

import pytest

from .grading import ADVICE, GRADE_TIMEOUT_S, REQUIRED, by_id, check, grade_class, others_pass

pytestmark = pytest.mark.timeout(GRADE_TIMEOUT_S + 60)
# The older message packages (com2009_msgs, tuos_ros_msgs) are the course template's: its calibration test covers them.
CLASS = ("course_template", "own_service_names", "ignores_invalid_input", "never_stops")
INVALID_TIMED_MOVES = ("timed_invalid_word", "timed_zero_duration", "timed_negative_duration")


@pytest.fixture(scope="module")
def graded(grader_env, tmp_path_factory):
    return grade_class(grader_env, CLASS, tmp_path_factory.mktemp("calibration"), "week4")


@pytest.mark.slow
def test_the_course_templates_habits_get_full_marks(graded):
    result = graded.results["course_template"]
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
    assert "[{0}/{0}]".format(len(CLASS)) in graded.output


@pytest.mark.slow
def test_other_file_names_and_one_service_name_for_two_parts_are_found_as_a_marker_would(graded):
    result = graded.results["course_template"]
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


@pytest.mark.slow
def test_services_under_the_students_own_names_are_found_by_type_and_pass(graded):
    result = graded.results["own_service_names"]
    others_pass(result)
    for name in ("/move_service", "/timed_move_service", "/approach_service"):
        service = result["services"][name]
        assert service["found_by"] == "by type" and service["found"] == "/my" + name.replace("/", "_"), service


@pytest.mark.slow
def test_a_timed_move_that_accepts_anything_fails_the_invalid_input_checks(graded):
    result = graded.results["ignores_invalid_input"]
    for check_id in INVALID_TIMED_MOVES:
        invalid = check(result, check_id)
        assert invalid["verdict"] == "fail", invalid
        assert "expected success False, it replied True" in invalid["reason"], invalid["reason"]
        assert invalid["evidence"]["reply"] == {"success": True}
    jump = check(result, "timed_invalid_word")
    assert "expected to stay within 0.01 m" in jump["reason"] and jump["evidence"]["motion"]["forward_m"] > 0.1
    others_pass(result, *INVALID_TIMED_MOVES)


@pytest.mark.slow
def test_a_robot_that_is_never_stopped_fails_the_move_check_still_moving(graded):
    result = graded.results["never_stops"]
    move = check(result, "move_true")
    assert move["verdict"] == "fail"
    assert "still moving" in move["reason"] and "expected the robot to be still" in move["reason"], move["reason"]
    motion = move["evidence"]["motion"]
    assert motion["still_at_end"] is False and motion["stopped_after_s"] is None, motion
    assert motion["end_v"] > 0.05
    others_pass(result, "move_true")
