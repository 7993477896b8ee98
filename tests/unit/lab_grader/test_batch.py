"""Sharding a class for job arrays, and the progress lines of a batch."""
import io

import pytest

from lab_grader.batch import Progress, Shard, latest_check, parse_shard


def test_shards_split_the_sorted_class_without_overlap():
    students = ["s{:02d}".format(i) for i in range(10)]
    pieces = [parse_shard("{}/3".format(k)).pick(students) for k in (1, 2, 3)]
    assert pieces[0] == ["s00", "s03", "s06", "s09"]
    assert sorted(sum(pieces, [])) == students


@pytest.mark.parametrize("text, reason", [("2", "K/N"), ("0/3", "1 <= K <= N"), ("4/3", "1 <= K <= N"),
                                          ("a/b", "K/N"), ("", "K/N")])
def test_bad_shards_are_refused(text, reason):
    with pytest.raises(ValueError, match=reason):
        parse_shard(text)


def test_a_shard_of_one_is_the_whole_class():
    assert Shard(1, 1).pick([3, 1, 2]) == [3, 1, 2]


def test_progress_says_what_was_done_and_what_is_left():
    out = io.StringIO()
    progress = Progress(total=4, out=out)
    progress.finished({"student": "alice", "score": 9, "max_score": 10, "duration_s": 42.0, "problems": [],
                       "checks": [{"verdict": "pass"}, {"verdict": "fail"}]})
    line = out.getvalue()
    assert line.startswith("[1/4] alice: 9/10 points, 1/2 checks passed, 42s (ETA ")


def test_the_status_line_names_each_workers_stage_and_latest_check(tmp_path):
    out = io.StringIO()
    progress = Progress(total=3, out=out)
    log = tmp_path / "checks.log"
    log.write_text("service /move_service: /move_service (by name, tuos_msgs/SetBool)\n"
                   "[1/17] pass  move_true (16/16): replied ...\n[2/17] fail  move_false (0/6): expected ...\n")
    progress.stage("bob", "building")
    progress.stage("alice", "checks", log)
    progress.status()
    assert out.getvalue() == ("[0/3 done] alice: checks, check 2/17 done (move_false: fail); bob: building "
                              "(ETA unknown)\n")
    progress.finished({"student": "alice", "score": 16, "max_score": 100, "duration_s": 30.0, "problems": [],
                       "checks": []})
    out.truncate(0)
    out.seek(0)
    progress.status()
    assert out.getvalue().startswith("[1/3 done] bob: building (ETA ")


def test_a_check_log_with_no_check_yet_shows_only_the_stage(tmp_path):
    assert latest_check(tmp_path / "missing.log") is None
    (tmp_path / "checks.log").write_text("service /move_service: not found\n")
    assert latest_check(tmp_path / "checks.log") is None
