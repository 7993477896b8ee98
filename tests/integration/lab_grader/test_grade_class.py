"""`rosrun lab_grader grade` on a small class of sample submissions (tests/integration/lab_grader/
sample_submissions.py: the lab's reference, copies with one typical mistake each, a package written from scratch
in a student's own style, and the calibration set's package in the course template's habits), graded in parallel in
their sandboxes in one run: each gets the verdicts its mistake deserves, with evidence; every report renders in a
real headless Chromium with its trajectory picture; and two shards merged give the files of one run.
(test_grade_hostile.py grades submissions that attack the sandbox.)

Calibration: the grader agrees with a marker who follows the Week 4 page. The lab's reference solution, and a
package written in the course template's habits (student_style/week4_course_template) - whole-second timing
(`rospy.get_rostime().secs`), publishers at module level, bare return values (a tuple for SetBool, a bool, a
string), the older message packages (tuos_ros_msgs, com2009_msgs), its own file names (timed_server.py,
approach_object_server.py) and Parts 1 and 2 both on /move_service. A marker gives both full marks; the grader's
verdicts, check by check, are stated in the tests at the end (they share the class's grade run: a run of their own
graded the reference a second time).
Part 5 (suites/part5.yaml): the lab's week5_actions (CameraSweep and Search) scores full marks, and a package whose
sweep saves files that are not images and whose Search server sends no feedback and drives on after its result
fails those three checks only; both are graded at once, in one grade run of their own after the Week 4 class."""
import csv
import json
import os
import subprocess

import pytest

from roslab.browser import HeadlessBrowser

from .sample_submissions import make_submission

GRADE_TIMEOUT_S = 900
# The class's grade run is the first test's set-up (about 450-580 s on two busy cores): pytest-timeout's 600 s per
# test would cut it before the grade command's own GRADE_TIMEOUT_S says it hangs.
pytestmark = pytest.mark.timeout(GRADE_TIMEOUT_S + 60)
# The older message packages (com2009_msgs, tuos_ros_msgs) are the course template's: its calibration test covers them.
CLASS = ("reference", "wrong_direction", "does_not_build", "student_style", "wrong_duration", "never_stops",
         "ignores_invalid_input", "bare_values", "own_service_names", "python2_syntax", "course_template")
PART5_CLASS = ("part5_reference", "part5_careless")
REAL_TIME_FACTOR = "2"   # the class and its rerun: a rerun compares like with like only at the same factor
TIMED_MOVES = {"timed_fwd": 2, "timed_back": 2, "timed_left": 3, "timed_right": 3}   # check: seconds requested
INVALID_TIMED_MOVES = ("timed_invalid_word", "timed_zero_duration", "timed_negative_duration")
REQUIRED = ("move_true", "move_false", "timed_fwd", "timed_back", "timed_left", "timed_right", "timed_invalid_word",
            "timed_zero_duration", "timed_negative_duration", "approach_stops_at_distance")
ADVICE = ("approach_velocity_too_fast", "approach_velocity_zero", "approach_velocity_negative",
          "approach_velocity_nan", "approach_distance_too_close", "approach_distance_out_of_range",
          "approach_distance_nan")


def grade(env, *args):
    run = subprocess.run(["rosrun", "lab_grader", "grade", *map(str, args)], env=env, capture_output=True, text=True,
                         timeout=GRADE_TIMEOUT_S)
    assert run.returncode == 0, run.stdout[-3000:] + run.stderr[-3000:]
    return run.stdout


def results(out):
    return {path.parent.name: json.loads(path.read_text()) for path in out.glob("*/result.json")}


def verdicts(result):
    return {check["id"]: check["verdict"] for check in result["checks"]}


def check(result, check_id):
    return next(check for check in result["checks"] if check["id"] == check_id)


def others_pass(result, *check_ids):
    """Every check but `check_ids` passed."""
    others = {check_id: verdict for check_id, verdict in verdicts(result).items() if check_id not in check_ids}
    assert others and set(others.values()) == {"pass"}, others


@pytest.fixture(scope="module")
def env(ros_master):
    """The ROS terminal's environment; the grader starts its own masters inside the sandboxes."""
    return dict(os.environ)


@pytest.fixture(scope="module")
def graded(env, tmp_path_factory):
    folder = tmp_path_factory.mktemp("class")
    for name in CLASS:
        make_submission(name, folder)
    out = tmp_path_factory.mktemp("grades")
    output = grade(env, folder, "--suite", "week4", "--out", out, "--jobs", "2", "--rtf", REAL_TIME_FACTOR)
    return out, output


@pytest.mark.slow
def test_the_reference_and_a_students_own_style_score_full_marks(graded):
    out, output = graded
    graded_results = results(out)
    for name in ("reference", "student_style"):
        result = graded_results[name]
        assert result["score"] == result["max_score"] > 0, json.dumps(result, indent=1)[:3000]
        assert set(verdicts(result).values()) == {"pass"}
    assert graded_results["student_style"]["packages"] == ["week4_alice"]
    assert {node["package"] for node in graded_results["student_style"]["nodes"]} == {"week4_alice"}
    assert "[{0}/{0}]".format(len(CLASS)) in output


@pytest.mark.slow
def test_driving_backwards_fails_the_move_check_with_the_evidence(graded):
    result = results(graded[0])["wrong_direction"]
    move = check(result, "move_true")
    assert move["verdict"] == "fail"
    assert move["evidence"]["motion"]["forward_m"] < -0.3
    others_pass(result, "move_true")


@pytest.mark.slow
def test_moving_for_twice_the_duration_fails_the_timed_moves_with_the_measured_duration(graded):
    result = results(graded[0])["wrong_duration"]
    for check_id, seconds in TIMED_MOVES.items():
        timed = check(result, check_id)
        assert timed["verdict"] == "fail", timed
        assert "expected the motion to last" in timed["reason"] and "it moved for" in timed["reason"], timed
        assert abs(timed["evidence"]["motion"]["duration_s"] - 2 * seconds) < 0.5, timed["evidence"]["motion"]
        assert timed["evidence"]["reply"] == {"success": True}
    others_pass(result, *TIMED_MOVES)


@pytest.mark.slow
def test_a_robot_that_is_never_stopped_fails_the_move_check_still_moving(graded):
    result = results(graded[0])["never_stops"]
    move = check(result, "move_true")
    assert move["verdict"] == "fail"
    assert "still moving" in move["reason"] and "expected the robot to be still" in move["reason"], move["reason"]
    motion = move["evidence"]["motion"]
    assert motion["still_at_end"] is False and motion["stopped_after_s"] is None, motion
    assert motion["end_v"] > 0.05
    others_pass(result, "move_true")


@pytest.mark.slow
def test_a_timed_move_that_accepts_anything_fails_the_invalid_input_checks(graded):
    result = results(graded[0])["ignores_invalid_input"]
    for check_id in INVALID_TIMED_MOVES:
        invalid = check(result, check_id)
        assert invalid["verdict"] == "fail", invalid
        assert "expected success False, it replied True" in invalid["reason"], invalid["reason"]
        assert invalid["evidence"]["reply"] == {"success": True}
    jump = check(result, "timed_invalid_word")
    assert "expected to stay within 0.01 m" in jump["reason"] and jump["evidence"]["motion"]["forward_m"] > 0.1
    others_pass(result, *INVALID_TIMED_MOVES)


@pytest.mark.slow
def test_bare_return_values_error_where_rospy_cannot_make_a_response_of_them(graded):
    """rospy makes a response of a tuple of every field (move_false) and of one value for a one-field response
    (TimedMovement), but `return True` for SetBool's two fields is an error answer to the caller."""
    result = results(graded[0])["bare_values"]
    move = check(result, "move_true")
    assert move["verdict"] == "error"
    assert "responded with an error" in move["reason"] and "handler returned invalid value" in move["reason"]
    assert move["evidence"]["server_error"] and move["evidence"]["reply"] is None
    assert move["evidence"]["motion"]["forward_m"] > 0.4, "it drove before it failed to answer"
    others_pass(result, "move_true")


@pytest.mark.slow
def test_services_under_the_students_own_names_are_found_by_type_and_pass(graded):
    result = results(graded[0])["own_service_names"]
    others_pass(result)
    for name in ("/move_service", "/timed_move_service", "/approach_service"):
        service = result["services"][name]
        assert service["found_by"] == "by type" and service["found"] == "/my" + name.replace("/", "_"), service


@pytest.mark.slow
def test_a_python2_print_statement_crashes_the_node_and_its_checks_say_so_with_the_traceback(graded):
    result = results(graded[0])["python2_syntax"]
    for check_id in ("move_true", "move_false"):
        move = check(result, check_id)
        assert move["verdict"] == "crashed", move
        assert move["reason"] == ("the node week4_services/nodes/move_server.py exited: SyntaxError: Missing "
                                  "parentheses in call to 'print'. Did you mean print(...)?"), move["reason"]
    others_pass(result, "move_true", "move_false")
    assert result["services"]["/move_service"]["found"] is None
    node = next(node for node in result["nodes"] if node["exercise"] == "move_server.py")
    assert node["crashed"] is True and node["running_at_end"] is False, node
    assert node["traceback"].splitlines()[-1].startswith("SyntaxError: Missing parentheses"), node["traceback"]
    assert all(node["running_at_end"] for node in result["nodes"] if node["exercise"] != "move_server.py")


@pytest.mark.slow
def test_a_package_that_does_not_build_gets_zero_and_catkins_error_lines(graded):
    result = results(graded[0])["does_not_build"]
    assert result["build"]["ok"] is False and result["score"] == 0
    assert result["build"]["errors"][0].startswith("CMake Error at week4_services/CMakeLists.txt"), result["build"]
    assert any("Parse error" in line for line in result["build"]["errors"])


@pytest.mark.slow
def test_the_class_csv_has_a_row_per_student(graded):
    rows = {row["student"]: row for row in csv.DictReader((graded[0] / "class.csv").open())}
    assert list(rows) == sorted(CLASS)
    assert rows["wrong_direction"]["move_true"] == "fail" and rows["does_not_build"]["builds"] == "no"
    assert rows["bare_values"]["move_true"] == "error" and rows["student_style"]["percent"] == "100.0"


@pytest.mark.slow
def test_the_reports_render_in_a_headless_browser_with_the_trajectory(graded):
    out = graded[0]
    browser = HeadlessBrowser()
    try:
        browser.driver.get((out / "reference" / "report.html").as_uri())
        assert browser.script("return document.getElementById('trajectory').naturalWidth;") > 100
        assert len(browser.driver.find_elements("css selector", "#checks tr")) > 5
        assert len(browser.driver.find_elements("css selector", "#services tr")) == 4   # a header and 3 services
        assert len(browser.driver.find_elements("css selector", "#nodes tr")) == 4
        browser.driver.get((out / "python2_syntax" / "report.html").as_uri())
        crashed = browser.script("return document.querySelector('#nodes pre.traceback').textContent;")
        assert "SyntaxError: Missing parentheses" in crashed
        assert "crashed" in browser.script("return document.querySelector('#checks').textContent;")
        browser.driver.get((out / "does_not_build" / "report.html").as_uri())
        assert "Parse error" in browser.script("return document.getElementById('build-errors').textContent;")
        browser.driver.get((out / "summary.html").as_uri())
        assert browser.script("return document.getElementById('histogram').naturalWidth;") > 100
        assert browser.console_errors() == []
    finally:
        browser.quit()


@pytest.mark.slow
def test_two_shards_merged_equal_one_run(env, tmp_path):
    """The whole run and the two shards run at once, as a job array's pieces may on one machine (each grader
    reserves its own slots); the suite without a world starts only roscore beside each build."""
    folder = tmp_path / "class"
    for student in ("ann", "ben", "cat"):
        make_submission("does_not_build", folder).rename(folder / student)
    runs = [subprocess.Popen(["rosrun", "lab_grader", "grade", str(folder), "--suite", "beginner_tutorials", "--out",
                              str(tmp_path / out), *shard], env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                             text=True)
            for out, shard in (("whole", ()), ("s1", ("--shard", "1/2")), ("s2", ("--shard", "2/2")))]
    try:
        for run in runs:
            output = run.communicate(timeout=GRADE_TIMEOUT_S)[0]
            assert run.returncode == 0, output[-3000:]
    finally:
        for run in runs:
            if run.poll() is None:
                run.kill()
                run.wait()
    grade(env, "--merge", tmp_path / "s1", tmp_path / "s2", "--out", tmp_path / "merged")
    assert sorted(p.name for p in (tmp_path / "s1").iterdir() if p.is_dir()) == ["ann", "cat"]
    for name in ("class.csv", "summary.json"):
        assert (tmp_path / "merged" / name).read_text() == (tmp_path / "whole" / name).read_text()


@pytest.mark.slow
def test_a_rerun_gives_identical_scores_and_verdicts(env, graded, tmp_path):
    """The same submissions graded again (same suite, same factor): the same score and the same verdict for every
    check, also where the measured motion decides (a duration, a direction)."""
    again = ("wrong_direction", "wrong_duration")
    for name in again:
        make_submission(name, tmp_path / "class")
    grade(env, tmp_path / "class", "--suite", "week4", "--out", tmp_path / "again", "--jobs", "2",
          "--rtf", REAL_TIME_FACTOR)
    first, second = results(graded[0]), results(tmp_path / "again")
    for name in again:
        assert (second[name]["score"], verdicts(second[name])) == (first[name]["score"], verdicts(first[name]))


# ---- calibration ----------------------------------------------------------------------------------------------------

def by_id(result):
    return {check["id"]: check for check in result["checks"]}


@pytest.mark.slow
def test_the_reference_passes_every_check_required_and_advice(graded):
    result = results(graded[0])["reference"]
    assert set(verdicts(result).values()) == {"pass"}, json.dumps(result["checks"], indent=1)[:3000]
    assert result["score"] == result["max_score"] == 100
    assert {check["id"]: check["kind"] for check in result["checks"]} == dict(
        [(check_id, "required") for check_id in REQUIRED] + [(check_id, "advice") for check_id in ADVICE])


@pytest.mark.slow
def test_the_course_templates_habits_get_full_marks(graded):
    result = results(graded[0])["course_template"]
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
    result = results(graded[0])["course_template"]
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


# ---- calibration: Part 5 -------------------------------------------------------------------------------------------

@pytest.fixture(scope="module")
def graded_part5(env, tmp_path_factory):
    folder = tmp_path_factory.mktemp("part5_class")
    for name in PART5_CLASS:
        make_submission(name, folder)
    out = tmp_path_factory.mktemp("part5_grades")
    grade(env, folder, "--suite", "part5", "--out", out, "--jobs", "2", "--rtf", REAL_TIME_FACTOR)
    return results(out)


@pytest.mark.slow
def test_part5_the_references_score_full_marks_measured_from_ground_truth(graded_part5):
    result = graded_part5["part5_reference"]
    assert set(verdicts(result).values()) == {"pass"}, json.dumps(result["checks"], indent=1)[:3000]
    assert result["score"] == result["max_score"] == 100
    checks = by_id(result)
    assert 85 < checks["sweep_90_4"]["evidence"]["motion"]["turn_deg"] < 95
    assert [fields["current_image"] for _, fields in checks["sweep_90_4"]["evidence"]["feedback"]] == [1, 2, 3, 4]
    assert checks["sweep_90_4"]["evidence"]["images"]["decodable"] == 4
    assert abs(checks["search_stops_at_distance"]["evidence"]["front_distance_m"] - 0.4) < 0.03
    assert abs(checks["search_stops_at_distance"]["evidence"]["motion"]["mean_speed_mps"] - 0.1) < 0.01
    assert {node["exercise"]: node["found_by"] for node in result["nodes"]} == dict.fromkeys(
        ("action_server.py", "search_server.py"), "the course's file name")


@pytest.mark.slow
def test_part5_unreadable_images_no_feedback_and_driving_on_fail_those_checks(graded_part5):
    result = graded_part5["part5_careless"]
    checks = by_id(result)
    sweep = checks["sweep_90_4"]
    assert sweep["verdict"] == "fail", sweep
    assert sweep["reason"].endswith("it holds 4 image files, 0 of them decodable"), sweep["reason"]
    stops = checks["search_stops_at_distance"]
    assert stops["verdict"] == "fail", stops
    assert "expected the robot to be still" in stops["reason"] and "it was moving" in stops["reason"], stops["reason"]
    assert stops["evidence"]["motion"]["end_v"] > 0.05
    feedback = checks["search_feedback_and_result"]
    assert feedback["verdict"] == "fail", feedback
    assert "expected at least 3 feedback messages, it sent 0" in feedback["reason"], feedback["reason"]
    others_pass(result, "sweep_90_4", "search_stops_at_distance", "search_feedback_and_result")
    assert result["score"] == 35
