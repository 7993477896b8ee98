"""Grading a class: the submissions of this shard, `jobs` at a time (one sandbox slot per worker thread), with a
progress line per finished submission, then the class CSV and summary. No ROS import.

Sharding is for existing job runners (Slurm arrays, Kubernetes Indexed Jobs, a CI matrix): shard K of N grades
the submissions whose position in the sorted list is K-1 modulo N, into its own output folder; `merge` then builds
the same class files from all the shards' folders as one run would.
"""
import re
import sys
import threading
import time
from concurrent.futures import ThreadPoolExecutor
from typing import List, NamedTuple, Sequence

SHARD_PATTERN = re.compile(r"^(\d+)/(\d+)$")


class Shard(NamedTuple):
    index: int   # 1-based, as Slurm's and the K/N
    count: int

    def pick(self, items: Sequence) -> List:
        return [item for position, item in enumerate(items) if position % self.count == self.index - 1]


def parse_shard(text: str) -> Shard:
    """"K/N" with 1 <= K <= N; ValueError naming the problem otherwise."""
    match = SHARD_PATTERN.match(text or "")
    if not match:
        raise ValueError("--shard must be K/N (e.g. 2/4), got {!r}".format(text))
    index, count = int(match.group(1)), int(match.group(2))
    if not 1 <= index <= count:
        raise ValueError("--shard K/N needs 1 <= K <= N, got {}/{}".format(index, count))
    return Shard(index, count)


def format_duration(seconds: float) -> str:
    seconds = max(0, int(round(seconds)))
    return "{}m{:02d}s".format(seconds // 60, seconds % 60) if seconds >= 60 else "{}s".format(seconds)


class Progress:
    """One line per finished submission: done/total, the student's score, and the time left at the pace so far."""

    def __init__(self, total: int, out=sys.stdout):
        self.total, self.done, self.out = total, 0, out
        self.started = time.monotonic()
        self._lock = threading.Lock()

    def finished(self, result: dict) -> None:
        with self._lock:
            self.done += 1
            elapsed = time.monotonic() - self.started
            left = elapsed / self.done * (self.total - self.done)
            passed = sum(check["verdict"] == "pass" for check in result["checks"])
            problem = "; " + result["problems"][0][:80] if result["problems"] else ""
            self.out.write("[{}/{}] {}: {:g}/{:g} points, {}/{} checks passed, {}{} (ETA {})\n".format(
                self.done, self.total, result["student"], result["score"], result["max_score"], passed,
                len(result["checks"]), format_duration(result.get("duration_s", 0)), problem,
                format_duration(left)))
            self.out.flush()


def grade_all(submissions, make_grader, out_root, jobs: int, progress: Progress) -> List[dict]:
    """Grade every submission, `jobs` at a time: `make_grader(slot)` gives a grader for one worker's slot (slots
    0..jobs-1), and each worker grades into out_root/<student>/."""
    slots = list(range(jobs))
    slot_lock = threading.Lock()
    local = threading.local()

    def grade_one(submission):
        if not hasattr(local, "grader"):
            with slot_lock:
                local.grader = make_grader(slots.pop(0))
        result = local.grader.grade(submission, out_root / submission.student_id)
        progress.finished(result)
        return result

    with ThreadPoolExecutor(max_workers=jobs, thread_name_prefix="grader") as pool:
        return list(pool.map(grade_one, submissions))
