"""`rosrun lab_grader grade` as the grader's tests run it, and the results it writes, read back: one sample class
graded (`grade_class`: the submissions made from sample_submissions.py, graded in one run) and the verdicts of a
student's result looked up by check. Shared by the test modules that grade classes (test_grade_*.py), each with a
class of its own: pytest-xdist runs those modules side by side, where one module grading them all one after the
other waited for ten minutes."""
import json
import subprocess
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path
from typing import Callable, Dict, NamedTuple, Optional, Sequence

from .sample_submissions import make_submission

GRADE_TIMEOUT_S = 900
JOBS = 2                 # submissions graded at once in a class run (two sandboxes, two simulators)
REAL_TIME_FACTOR = 2     # the week4 classes and their rerun: a rerun compares like with like only at the same factor
# The week4 suite's checks by kind: the required ones make its 100 points, the advice ones score 0.
REQUIRED = ("move_true", "move_false", "timed_fwd", "timed_back", "timed_left", "timed_right", "timed_invalid_word",
            "timed_zero_duration", "timed_negative_duration", "approach_stops_at_distance")
ADVICE = ("approach_velocity_too_fast", "approach_velocity_zero", "approach_velocity_negative",
          "approach_velocity_nan", "approach_distance_too_close", "approach_distance_out_of_range",
          "approach_distance_nan")


def grade(env, *args):
    """`rosrun lab_grader grade ARGS` to its end, which must be a success; returns its stdout."""
    run = subprocess.run(["rosrun", "lab_grader", "grade", *map(str, args)], env=env, capture_output=True, text=True,
                         timeout=GRADE_TIMEOUT_S)
    assert run.returncode == 0, run.stdout[-3000:] + run.stderr[-3000:]
    return run.stdout


def results(out) -> Dict[str, dict]:
    """{student: their result.json} of a grade run's output folder."""
    return {path.parent.name: json.loads(path.read_text()) for path in Path(out).glob("*/result.json")}


class GradedClass(NamedTuple):
    out: Path                  # the grade run's output folder
    output: str                # what it printed
    results: Dict[str, dict]   # {student: result}


def grade_class(env, names: Sequence[str], work: Path, suite, rtf=REAL_TIME_FACTOR, jobs=JOBS,
                fill: Optional[Dict[str, str]] = None) -> GradedClass:
    """The sample submissions `names` (sample_submissions.make_submission, with `fill`) made in work/class and
    graded in one run with `suite` (a name or a suite file), `jobs` at a time, the simulator at `rtf`, into
    work/grades."""
    folder, out = Path(work) / "class", Path(work) / "grades"
    for name in names:
        make_submission(name, folder, fill)
    output = grade(env, folder, "--suite", suite, "--out", out, "--jobs", jobs, "--rtf", rtf)
    return GradedClass(out, output, results(out))


def at_once(*lanes: Callable[[], object]) -> list:
    """Call each of `lanes` in a thread of its own, all started together; returns their answers in the same order.
    A lane that grades (grade_class, one class or several one after the other) reserves sandbox slots of its own,
    as a second grader on the same machine does. Where a module grades two classes, the second no longer waits for
    the first: a week4 grading spends most of its wall time waiting on the simulator's clock."""
    with ThreadPoolExecutor(len(lanes)) as pool:
        runs = [pool.submit(lane) for lane in lanes]
        return [run.result() for run in runs]


def verdicts(result) -> Dict[str, str]:
    return {check["id"]: check["verdict"] for check in result["checks"]}


def by_id(result) -> Dict[str, dict]:
    return {check["id"]: check for check in result["checks"]}


def check(result, check_id) -> dict:
    return by_id(result)[check_id]


def others_pass(result, *check_ids):
    """Every check but `check_ids` passed."""
    others = {check_id: verdict for check_id, verdict in verdicts(result).items() if check_id not in check_ids}
    assert others and set(others.values()) == {"pass"}, others
