"""Grading a class: the submissions of this shard, `jobs` at a time (one sandbox slot per worker thread), with a
progress line per finished submission and, every STATUS_EVERY_S while work goes on, a status line of what each
worker is doing (building, starting, which check), then the class CSV and summary. No ROS import.

Sharding is for existing job runners (Slurm arrays, Kubernetes Indexed Jobs, a CI matrix): shard K of N grades
the submissions whose position in the sorted list is K-1 modulo N, into its own output folder; `merge` then builds
the same class files from all the shards' folders as one run would.
"""
import re
import sys
import threading
import time
from concurrent.futures import ThreadPoolExecutor
from typing import Dict, List, NamedTuple, Optional, Sequence

SHARD_PATTERN = re.compile(r"^(\d+)/(\d+)$")
STATUS_EVERY_S = 15.0
CHECK_LINE = re.compile(r"^\[(\d+)/(\d+)\] (\w+)\s+(\S+)", re.MULTILINE)   # run_checks: "[3/17] pass  timed_fwd ..."
CHECK_LOG_TAIL_BYTES = 4096


def latest_check(log_path) -> Optional[str]:
    """'check 3/17 done (timed_fwd: pass)' from the end of a run_checks log, or None before the first check."""
    try:
        with open(log_path, "rb") as log:
            log.seek(0, 2)
            log.seek(max(0, log.tell() - CHECK_LOG_TAIL_BYTES))
            tail = log.read().decode("utf-8", "replace")
    except OSError:
        return None
    matches = CHECK_LINE.findall(tail)
    if not matches:
        return None
    number, total, verdict, check_id = matches[-1]
    return "check {}/{} done ({}: {})".format(number, total, check_id, verdict)


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
    """One line per finished submission: done/total, the student's score, and the time left at the pace so far;
    and on request (`status`) one line of what each worker is doing now, from the stages the graders report
    (`stage(student, what, checks_log=None)`: with a check log, the latest check finished is read from it)."""

    def __init__(self, total: int, out=sys.stdout):
        self.total, self.done, self.out = total, 0, out
        self.started = time.monotonic()
        self._lock = threading.Lock()
        self._stages: Dict[str, tuple] = {}     # student -> (what, checks log or None)

    def stage(self, student: str, what: str, checks_log=None) -> None:
        with self._lock:
            self._stages[student] = (what, checks_log)

    def eta(self) -> str:
        if not self.done:
            return "ETA unknown"
        elapsed = time.monotonic() - self.started
        return "ETA " + format_duration(elapsed / self.done * (self.total - self.done))

    def status(self) -> None:
        """One line: done/total, each active student's stage (and latest check), the ETA."""
        with self._lock:
            stages = sorted(self._stages.items())
            parts = []
            for student, (what, checks_log) in stages:
                check = latest_check(checks_log) if checks_log is not None else None
                parts.append("{}: {}{}".format(student, what, ", " + check if check else ""))
            if parts:
                self.out.write("[{}/{} done] {} ({})\n".format(self.done, self.total, "; ".join(parts), self.eta()))
                self.out.flush()

    def finished(self, result: dict) -> None:
        with self._lock:
            self._stages.pop(result["student"], None)
            self.done += 1
            passed = sum(check["verdict"] == "pass" for check in result["checks"])
            problem = "; " + result["problems"][0][:80] if result["problems"] else ""
            self.out.write("[{}/{}] {}: {:g}/{:g} points, {}/{} checks passed, {}{} ({})\n".format(
                self.done, self.total, result["student"], result["score"], result["max_score"], passed,
                len(result["checks"]), format_duration(result.get("duration_s", 0)), problem, self.eta()))
            self.out.flush()


def grade_all(submissions, make_grader, out_root, jobs: int, progress: Progress) -> List[dict]:
    """Grade every submission, `jobs` at a time: `make_grader()` gives a grader for one worker (made once per
    worker thread, in that thread), and each worker grades into out_root/<student>/, reporting its stages to
    `progress`; a status line is printed every STATUS_EVERY_S until all are done."""
    local = threading.local()

    def grade_one(submission):
        if not hasattr(local, "grader"):
            local.grader = make_grader()
        result = local.grader.grade(submission, out_root / submission.student_id,
                                    on_stage=lambda what, log=None: progress.stage(submission.student_id, what, log))
        progress.finished(result)
        return result

    all_done = threading.Event()

    def report_status():
        while not all_done.wait(STATUS_EVERY_S):
            progress.status()

    reporter = threading.Thread(target=report_status, daemon=True, name="grade-status")
    reporter.start()
    try:
        with ThreadPoolExecutor(max_workers=jobs, thread_name_prefix="grader") as pool:
            return list(pool.map(grade_one, submissions))
    finally:
        all_done.set()
        reporter.join()
