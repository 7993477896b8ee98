"""Sharding a class for job arrays, and the progress lines of a batch."""
import io

import pytest

from lab_grader.batch import Progress, Shard, parse_shard


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
