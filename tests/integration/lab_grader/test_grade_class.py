"""`rosrun lab_grader grade` on a small class of sample submissions (sample_submissions.py: the lab's reference,
copies with one typical mistake each, and a package written from scratch in a student's own style), graded in
parallel in their sandboxes in one run: each gets the verdicts its mistake deserves, with evidence; every report
renders in a real headless Chromium with its trajectory picture; and two shards merged give the files of one run.

The other sample classes are graded by modules of their own, which pytest-xdist runs beside this one:
test_grade_calibration.py (the course template's habits and other mistakes), test_grade_rerun.py (mistakes the
measured motion decides, graded twice), test_grade_part5.py (Part 5's actions) and test_grade_hostile.py
(submissions that attack the sandbox)."""
import csv
import json
import subprocess

import pytest

from roslab.browser import HeadlessBrowser

from .grading import ADVICE, GRADE_TIMEOUT_S, REQUIRED, check, grade, grade_class, others_pass, verdicts
from .sample_submissions import make_submission

# The class's grade run is the first test's set-up: pytest-timeout's 600 s per test would cut it on very busy cores
# before the grade command's own GRADE_TIMEOUT_S says it hangs.
pytestmark = pytest.mark.timeout(GRADE_TIMEOUT_S + 60)
CLASS = ("reference", "student_style", "does_not_build", "python2_syntax", "bare_values")


@pytest.fixture(scope="module")
def graded(grader_env, tmp_path_factory):
    return grade_class(grader_env, CLASS, tmp_path_factory.mktemp("class"), "week4")


@pytest.mark.slow
def test_the_reference_and_a_students_own_style_score_full_marks(graded):
    for name in ("reference", "student_style"):
        result = graded.results[name]
        assert result["score"] == result["max_score"] > 0, json.dumps(result, indent=1)[:3000]
        assert set(verdicts(result).values()) == {"pass"}
    assert graded.results["student_style"]["packages"] == ["week4_alice"]
    assert {node["package"] for node in graded.results["student_style"]["nodes"]} == {"week4_alice"}
    assert "[{0}/{0}]".format(len(CLASS)) in graded.output
    assert "grade: note: the simulator at 2x, faster than the 1x this suite is calibrated at" in graded.output


@pytest.mark.slow
def test_the_reference_passes_every_check_required_and_advice(graded):
    result = graded.results["reference"]
    assert set(verdicts(result).values()) == {"pass"}, json.dumps(result["checks"], indent=1)[:3000]
    assert result["score"] == result["max_score"] == 100
    assert {check["id"]: check["kind"] for check in result["checks"]} == dict(
        [(check_id, "required") for check_id in REQUIRED] + [(check_id, "advice") for check_id in ADVICE])
    for name in ("/move_service", "/timed_move_service", "/approach_service"):
        assert (result["services"][name]["found"], result["services"][name]["found_by"]) == (name, "by name")
    move = check(result, "move_true")["evidence"]
    assert move["reply"]["response_signal"] is True
    assert move["motion"]["forward_m"] == pytest.approx(0.5, abs=0.03)
    assert move["motion"]["duration_s"] == pytest.approx(5.0, abs=0.3)
    assert 10 < len(move["trajectory"]) <= 400
    assert check(result, "approach_stops_at_distance")["evidence"]["front_distance_m"] == pytest.approx(0.4, abs=0.05)
    assert check(result, "approach_distance_nan")["evidence"]["request"]["approach_distance"] == "nan"


@pytest.mark.slow
def test_bare_return_values_error_where_rospy_cannot_make_a_response_of_them(graded):
    """rospy makes a response of a tuple of every field (move_false) and of one value for a one-field response
    (TimedMovement), but `return True` for SetBool's two fields is an error answer to the caller."""
    result = graded.results["bare_values"]
    move = check(result, "move_true")
    assert move["verdict"] == "error"
    assert "responded with an error" in move["reason"] and "handler returned invalid value" in move["reason"]
    assert move["evidence"]["server_error"] and move["evidence"]["reply"] is None
    assert move["evidence"]["motion"]["forward_m"] > 0.4, "it drove before it failed to answer"
    others_pass(result, "move_true")


@pytest.mark.slow
def test_a_python2_print_statement_crashes_the_node_and_its_checks_say_so_with_the_traceback(graded):
    result = graded.results["python2_syntax"]
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
    result = graded.results["does_not_build"]
    assert result["build"]["ok"] is False and result["score"] == 0
    assert result["build"]["errors"][0].startswith("CMake Error at week4_services/CMakeLists.txt"), result["build"]
    assert any("Parse error" in line for line in result["build"]["errors"])


@pytest.mark.slow
def test_the_class_csv_has_a_row_per_student(graded):
    rows = {row["student"]: row for row in csv.DictReader((graded.out / "class.csv").open())}
    assert list(rows) == sorted(CLASS)
    assert rows["python2_syntax"]["move_true"] == "crashed" and rows["does_not_build"]["builds"] == "no"
    assert rows["bare_values"]["move_true"] == "error" and rows["student_style"]["percent"] == "100.0"


@pytest.mark.slow
def test_the_reports_render_in_a_headless_browser_with_the_trajectory(graded):
    browser = HeadlessBrowser()
    try:
        browser.driver.get((graded.out / "reference" / "report.html").as_uri())
        assert browser.script("return document.getElementById('trajectory').naturalWidth;") > 100
        assert len(browser.driver.find_elements("css selector", "#checks tr")) > 5
        assert len(browser.driver.find_elements("css selector", "#services tr")) == 4   # a header and 3 services
        assert len(browser.driver.find_elements("css selector", "#nodes tr")) == 4
        browser.driver.get((graded.out / "python2_syntax" / "report.html").as_uri())
        crashed = browser.script("return document.querySelector('#nodes pre.traceback').textContent;")
        assert "SyntaxError: Missing parentheses" in crashed
        assert "crashed" in browser.script("return document.querySelector('#checks').textContent;")
        browser.driver.get((graded.out / "does_not_build" / "report.html").as_uri())
        assert "Parse error" in browser.script("return document.getElementById('build-errors').textContent;")
        browser.driver.get((graded.out / "summary.html").as_uri())
        assert browser.script("return document.getElementById('histogram').getBoundingClientRect().width;") > 100
        assert browser.script("return [...document.querySelectorAll('#histogram rect.bar')]"
                              ".reduce((sum, bar) => sum + Number(bar.dataset.students), 0);") == len(CLASS)
        assert browser.console_errors() == []
    finally:
        browser.quit()


@pytest.mark.slow
def test_two_shards_merged_equal_one_run(grader_env, tmp_path):
    """The whole run and the two shards run at once, as a job array's pieces may on one machine (each grader
    reserves its own slots); the suite without a world starts only roscore beside each build."""
    folder = tmp_path / "class"
    for student in ("ann", "ben", "cat"):
        make_submission("does_not_build", folder).rename(folder / student)
    runs = [subprocess.Popen(["rosrun", "lab_grader", "grade", str(folder), "--suite", "beginner_tutorials", "--out",
                              str(tmp_path / out), *shard], env=grader_env, stdout=subprocess.PIPE,
                             stderr=subprocess.STDOUT, text=True)
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
    grade(grader_env, "--merge", tmp_path / "s1", tmp_path / "s2", "--out", tmp_path / "merged")
    assert sorted(p.name for p in (tmp_path / "s1").iterdir() if p.is_dir()) == ["ann", "cat"]
    for name in ("class.csv", "summary.json"):
        assert (tmp_path / "merged" / name).read_text() == (tmp_path / "whole" / name).read_text()
