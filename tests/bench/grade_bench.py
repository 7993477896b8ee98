"""lab_grader benchmarks for scripts/bench (wall-clock figures; never asserted):

- wall time to grade one Week 4 submission (the lab's reference) at real-time factor 1 (target <= 60 s) and 2
  (target <= 35 s), and where the time goes at each factor (the stages result.json records: building, starting
  the simulator, and per exercise finding its node and its checks, summed here);
- wall time to grade one Part 5 submission (the lab's week5_actions: CameraSweep and Search, suites/part5.yaml) at
  factor 1 (target <= 90 s), and its stages;
- wall time to grade one Part 6 submission (the lab's week6_vision: colour search and line follower,
  suites/part6.yaml) at factor 1 (target <= 180 s: its two runs alone are 120 s of sim time, 75 s of colour search
  and 45 s of line following after the robot's first motion, and the line follower's world needs a simulator of
  its own), and its stages;
- how many check verdicts of the distinct samples (tests/integration/lab_grader/sample_submissions.py: every
  mistake and every self-contained hostile one) are the same at factor 2 as at factor 1: all of them, or the faster
  factor would not be used;
- wall time to grade a class of CLASS_SIZE sample submissions (each sample in turn), 2 at a time at factor 2
  (target <= 10 min on 2 cores).

    source scripts/env.sh && python3 tests/bench/grade_bench.py [class size]      (as root, like the grader)
    (class size 0: only the single submission at each factor)
"""
import json
import subprocess
import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from integration.lab_grader.sample_submissions import SELF_CONTAINED, make_submission  # noqa: E402

CLASS_SIZE = 20
FAST_FACTOR = 2
ONE_TARGET_S = {1: 60.0, 2: 35.0}
PART5_TARGET_S = 90.0
PART6_TARGET_S = 180.0
CLASS_TARGET_S = 600.0
STAGES = ("building (and starting the simulator)", "starting the simulator", "starting its world", "finding its node",
          "checks", "closing")


def grade(folder, out, factor, jobs, suite="week4"):
    """Wall seconds of `rosrun lab_grader grade` on `folder`, and {student: its result}."""
    started = time.monotonic()
    subprocess.run(["rosrun", "lab_grader", "grade", str(folder), "--suite", suite, "--out", str(out),
                    "--jobs", str(jobs), "--rtf", str(factor)], check=True, stdout=subprocess.DEVNULL)
    elapsed = time.monotonic() - started
    return elapsed, {path.parent.name: json.loads(path.read_text()) for path in Path(out).glob("*/result.json")}


def verdicts(results):
    return {student: {check["id"]: check["verdict"] for check in result["checks"]}
            for student, result in results.items()}


def print_stages(label, result):
    stages = result["stage_s"]
    print("{}: {}".format(label, ", ".join("{} {:.1f} s".format(stage, sum(
        seconds for name, seconds in stages.items() if name == stage or name.endswith(": " + stage)))
        for stage in STAGES)))


def run(class_size=CLASS_SIZE):
    rows = []
    with tempfile.TemporaryDirectory(prefix="grade-bench-") as workdir:
        work = Path(workdir)
        make_submission("reference", work / "one")
        for factor in (1, FAST_FACTOR):
            seconds, results = grade(work / "one", work / "one-out-{}".format(factor), factor, jobs=1)
            rows.append(("grade one Week 4 submission (reference), factor {}".format(factor), seconds, "s",
                         ONE_TARGET_S[factor], "<="))
            print_stages("week4, factor {}".format(factor), results["reference"])
        make_submission("part5_reference", work / "part5")
        seconds, results = grade(work / "part5", work / "part5-out", 1, jobs=1, suite="part5")
        rows.append(("grade one Part 5 submission (reference), factor 1", seconds, "s", PART5_TARGET_S, "<="))
        print_stages("part5, factor 1", results["part5_reference"])
        make_submission("part6_reference", work / "part6")
        seconds, results = grade(work / "part6", work / "part6-out", 1, jobs=1, suite="part6")
        rows.append(("grade one Part 6 submission (reference), factor 1", seconds, "s", PART6_TARGET_S, "<="))
        print_stages("part6, factor 1", results["part6_reference"])
        if not class_size:
            return rows
        for name in SELF_CONTAINED:
            make_submission(name, work / "distinct")
        _, slow = grade(work / "distinct", work / "distinct-1", 1, jobs=2)
        _, fast = grade(work / "distinct", work / "distinct-{}".format(FAST_FACTOR), FAST_FACTOR, jobs=2)
        slow, fast = verdicts(slow), verdicts(fast)
        checks = [(student, check) for student in slow for check in slow[student]]
        same = sum(slow[student][check] == fast.get(student, {}).get(check) for student, check in checks)
        rows.append(("check verdicts of {} samples alike at factor {} and 1".format(len(SELF_CONTAINED),
                                                                                  FAST_FACTOR),
                     same, "checks", len(checks), ">="))
        for index in range(class_size):
            make_submission(SELF_CONTAINED[index % len(SELF_CONTAINED)], work / "class").rename(
                work / "class" / "student{:02d}".format(index + 1))
        seconds, _ = grade(work / "class", work / "class-out", FAST_FACTOR, jobs=2)
        rows.append(("grade a class of {} samples, 2 at a time, factor {}".format(class_size, FAST_FACTOR), seconds,
                     "s", CLASS_TARGET_S, "<="))
    return rows


if __name__ == "__main__":
    from report import print_table
    print_table(run(int(sys.argv[1]) if len(sys.argv) > 1 else CLASS_SIZE))
