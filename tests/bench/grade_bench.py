"""lab_grader benchmarks for scripts/bench (wall-clock figures; never asserted):

- wall time to grade one Week 4 submission (the lab's reference) at real-time factor 1 and 2 (target <= 45 s);
- wall time to grade a class of CLASS_SIZE sample submissions (tests/integration/lab_grader/sample_submissions.py,
  each mistake in turn), 2 at a time at factor 2 (target <= 10 min on 2 cores);
- how many check verdicts of the distinct samples are the same at factor 2 as at factor 1 (all of them, or the
  faster factor would not be used).

    source scripts/env.sh && python3 tests/bench/grade_bench.py [class size]
"""
import json
import subprocess
import sys
import tempfile
import time
from pathlib import Path

TESTS = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(TESTS / "integration" / "lab_grader"))

from sample_submissions import MISTAKES, make_submission  # noqa: E402  (needs the sys.path entry above)

CLASS_SIZE = 20
FAST_FACTOR = 2
ONE_TARGET_S = 45.0
CLASS_TARGET_S = 600.0


def grade(folder, out, factor, jobs):
    """Wall seconds of `rosrun lab_grader grade` on `folder`, and {student: {check: verdict}}."""
    started = time.monotonic()
    subprocess.run(["rosrun", "lab_grader", "grade", str(folder), "--suite", "week4", "--out", str(out),
                    "--jobs", str(jobs), "--rtf", str(factor)], check=True, stdout=subprocess.DEVNULL)
    elapsed = time.monotonic() - started
    verdicts = {path.parent.name: {check["id"]: check["verdict"] for check in json.loads(path.read_text())["checks"]}
                for path in Path(out).glob("*/result.json")}
    return elapsed, verdicts


def run(class_size=CLASS_SIZE):
    rows = []
    with tempfile.TemporaryDirectory(prefix="grade-bench-") as workdir:
        work = Path(workdir)
        make_submission("reference", work / "one")
        for factor in (1, FAST_FACTOR):
            seconds, _ = grade(work / "one", work / "one-out-{}".format(factor), factor, jobs=1)
            rows.append(("grade one Week 4 submission (reference), factor {}".format(factor), seconds, "s",
                         ONE_TARGET_S, "<="))
        for name in MISTAKES:
            make_submission(name, work / "distinct")
        _, slow = grade(work / "distinct", work / "distinct-1", 1, jobs=2)
        _, fast = grade(work / "distinct", work / "distinct-{}".format(FAST_FACTOR), FAST_FACTOR, jobs=2)
        checks = [(student, check) for student in slow for check in slow[student]]
        same = sum(slow[student][check] == fast.get(student, {}).get(check) for student, check in checks)
        rows.append(("check verdicts of {} samples alike at factor {} and 1".format(len(MISTAKES), FAST_FACTOR),
                     same, "checks", len(checks), ">="))
        names = list(MISTAKES)
        for index in range(class_size):
            make_submission(names[index % len(names)], work / "class").rename(
                work / "class" / "student{:02d}".format(index + 1))
        seconds, _ = grade(work / "class", work / "class-out", FAST_FACTOR, jobs=2)
        rows.append(("grade a class of {} samples, 2 at a time, factor {}".format(class_size, FAST_FACTOR), seconds,
                     "s", CLASS_TARGET_S, "<="))
    return rows


if __name__ == "__main__":
    from report import print_table
    print_table(run(int(sys.argv[1]) if len(sys.argv) > 1 else CLASS_SIZE))
