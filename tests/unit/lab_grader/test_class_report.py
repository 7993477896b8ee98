"""The class files: one CSV row per student with every check's verdict, and a summary of the most failed checks;
built from the result files alone, so shards merge into what one run writes."""
import json
import re

import pytest

from lab_grader.class_report import class_csv, read_results, summary, write_class_report
from lab_grader.summary_html import histogram_counts, score_histogram_svg


def result(student, verdicts, builds=True):
    checks = [{"id": check_id, "verdict": verdict, "weight": 1} for check_id, verdict in verdicts.items()]
    return {"student": student, "score": float(sum(v == "pass" for v in verdicts.values())),
            "max_score": 3.0, "checks": checks, "build": {"ok": builds}, "problems": []}


CLASS = [result("bob", {"move": "pass", "timed": "fail", "approach": "error"}),
         result("alice", {"move": "pass", "timed": "pass", "approach": "pass"}),
         result("carol", {}, builds=False)]


def write(folder, results):
    for entry in results:
        (folder / entry["student"]).mkdir(parents=True)
        (folder / entry["student"] / "result.json").write_text(json.dumps(entry))


def test_the_csv_has_a_row_per_student_in_order(tmp_path):
    write(tmp_path, CLASS)
    assert class_csv(read_results([tmp_path])).splitlines() == [
        "student,score,max_score,percent,builds,move,timed,approach",
        "alice,3,3,100.0,yes,pass,pass,pass",
        "bob,1,3,33.3,yes,pass,fail,error",
        "carol,0,3,0.0,no,not run,not run,not run"]


def test_the_summary_lists_the_most_failed_checks_first(tmp_path):
    write(tmp_path, CLASS)
    # ties keep the suite's order; a check that did not run (carol's build failed) counts as failed
    assert summary(read_results([tmp_path]))["most_failed"] == [("timed", 2), ("approach", 2), ("move", 1)]


def test_merged_shards_equal_one_run(tmp_path):
    write(tmp_path / "one", CLASS)
    write(tmp_path / "shard1", CLASS[:1])
    write(tmp_path / "shard2", CLASS[1:])
    write_class_report(read_results([tmp_path / "one"]), tmp_path / "one")
    write_class_report(read_results([tmp_path / "shard1", tmp_path / "shard2"]), tmp_path / "merged")
    for name in ("class.csv", "summary.json"):
        assert (tmp_path / "one" / name).read_text() == (tmp_path / "merged" / name).read_text()


def test_overlapping_shards_are_refused(tmp_path):
    write(tmp_path / "a", CLASS[:1])
    write(tmp_path / "b", CLASS[:1])
    with pytest.raises(ValueError, match="two places"):
        read_results([tmp_path / "a", tmp_path / "b"])


def test_the_histogram_puts_every_student_in_one_bin_a_full_score_in_the_last():
    edges, counts = histogram_counts([0, 4.9, 5, 99, 100, 100], 100)
    assert len(counts) == 20 and edges[0] == 0 and edges[-1] == 100
    assert counts[0] == 2 and counts[1] == 1 and counts[-1] == 3 and sum(counts) == 6
    assert histogram_counts([0, 1, 3], 3)[1] == [1, 1, 1]     # under 20 points: a bin per point


def test_the_histogram_svg_has_a_bar_per_bin_holding_its_students():
    svg = score_histogram_svg([10, 10, 55, 100], 100)
    students = [int(n) for n in re.findall(r"data-students='(\d+)'", svg)]
    assert len(students) == 20 and sum(students) == 4 and students[2] == 2
    heights = [float(h) for h in re.findall(r"class='bar'[^>]* height='([\d.]+)'", svg)]
    assert heights[2] == max(heights) == 2 * heights[11] > 0      # bar height in proportion to its students
    assert "Score distribution (4 students)" in svg and "score (of 100)" in svg
