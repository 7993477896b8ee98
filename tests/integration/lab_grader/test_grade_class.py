"""`rosrun lab_grader grade` on a small class of sample submissions (tests/integration/lab_grader/
sample_submissions.py: the lab's reference and copies with one typical mistake each), graded in parallel in their
sandboxes: each gets the verdicts its mistake deserves, with evidence; every report renders in a real headless
Chromium with its trajectory picture; and two shards merged give the files of one run."""
import csv
import json
import os
import subprocess

import pytest

from roslab.browser import HeadlessBrowser

from .sample_submissions import make_submission

GRADE_TIMEOUT_S = 900


def grade(env, *args):
    run = subprocess.run(["rosrun", "lab_grader", "grade", *map(str, args)], env=env, capture_output=True, text=True,
                         timeout=GRADE_TIMEOUT_S)
    assert run.returncode == 0, run.stdout[-3000:] + run.stderr[-3000:]
    return run.stdout


def results(out):
    return {path.parent.name: json.loads(path.read_text()) for path in out.glob("*/result.json")}


def verdicts(result):
    return {check["id"]: check["verdict"] for check in result["checks"]}


@pytest.fixture(scope="module")
def env(ros_master):
    """The ROS terminal's environment; the grader starts its own masters inside the sandboxes."""
    return dict(os.environ)


@pytest.fixture(scope="module")
def graded(env, tmp_path_factory):
    folder = tmp_path_factory.mktemp("class")
    for name in ("reference", "wrong_direction", "old_message_package", "does_not_build"):
        make_submission(name, folder)
    out = tmp_path_factory.mktemp("grades")
    output = grade(env, folder, "--suite", "week4", "--out", out, "--jobs", "2", "--rtf", "2")
    return out, output


@pytest.mark.slow
def test_the_reference_and_the_old_message_package_score_full_marks(graded):
    out, output = graded
    graded_results = results(out)
    for name in ("reference", "old_message_package"):
        result = graded_results[name]
        assert result["score"] == result["max_score"] > 0, json.dumps(result, indent=1)[:3000]
        assert set(verdicts(result).values()) == {"pass"}
    assert "[4/4]" in output


@pytest.mark.slow
def test_driving_backwards_fails_the_move_check_with_the_evidence(graded):
    result = results(graded[0])["wrong_direction"]
    move = next(check for check in result["checks"] if check["id"] == "move_true")
    assert move["verdict"] == "fail"
    assert move["evidence"]["motion"]["forward_m"] < -0.3
    others = {check_id: verdict for check_id, verdict in verdicts(result).items() if check_id != "move_true"}
    assert set(others.values()) == {"pass"}, others


@pytest.mark.slow
def test_a_package_that_does_not_build_gets_zero_and_its_build_log(graded):
    result = results(graded[0])["does_not_build"]
    assert result["build"]["ok"] is False and result["score"] == 0
    assert "CMake Error" in result["build"]["log_tail"] or "Parse error" in result["build"]["log_tail"]


@pytest.mark.slow
def test_the_class_csv_has_a_row_per_student(graded):
    rows = list(csv.DictReader((graded[0] / "class.csv").open()))
    assert [row["student"] for row in rows] == ["does_not_build", "old_message_package", "reference",
                                                "wrong_direction"]
    assert rows[3]["move_true"] == "fail" and rows[0]["builds"] == "no"


@pytest.mark.slow
def test_the_reports_render_in_a_headless_browser_with_the_trajectory(graded):
    out = graded[0]
    browser = HeadlessBrowser()
    try:
        browser.driver.get((out / "reference" / "report.html").as_uri())
        assert browser.script("return document.getElementById('trajectory').naturalWidth;") > 100
        assert len(browser.driver.find_elements("css selector", "#checks tr")) > 5
        browser.driver.get((out / "summary.html").as_uri())
        assert browser.script("return document.getElementById('histogram').naturalWidth;") > 100
        assert browser.console_errors() == []
    finally:
        browser.quit()


@pytest.mark.slow
def test_two_shards_merged_equal_one_run(env, tmp_path):
    folder = tmp_path / "class"
    for student in ("ann", "ben", "cat"):
        make_submission("does_not_build", folder).rename(folder / student)
    grade(env, folder, "--suite", "week4", "--out", tmp_path / "whole")
    grade(env, folder, "--suite", "week4", "--out", tmp_path / "s1", "--shard", "1/2")
    grade(env, folder, "--suite", "week4", "--out", tmp_path / "s2", "--shard", "2/2")
    grade(env, "--merge", tmp_path / "s1", tmp_path / "s2", "--out", tmp_path / "merged")
    assert sorted(p.name for p in (tmp_path / "s1").iterdir() if p.is_dir()) == ["ann", "cat"]
    for name in ("class.csv", "summary.json"):
        assert (tmp_path / "merged" / name).read_text() == (tmp_path / "whole" / name).read_text()
