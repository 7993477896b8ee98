"""Verdicts, scoring and the results file of a check run (plain Python, no ROS).

The results file (JSON, schema `RESULTS_SCHEMA`), written atomically by `write_results`:

    {
      "schema": "lab_grader.results/1",
      "suite": "week4",
      "services": {                           # one entry per service of the suite, by the name the course asks for
        "/move_service": {"expected_type": "tuos_msgs/SetBool",
                          "found": "/move_service" | "/other_name" | null,
                          "found_by": "by name" | "by type" | null,
                          "found_type": "tuos_msgs/SetBool" | "com2009_msgs/SetBool" | null,
                          "note": "..." | null},
        ...
      },
      "checks": [
        {"id": "move_true", "title": "...", "kind": "required" | "advice", "weight": 16,
         "verdict": "pass" | "fail" | "error" | "interference" | "crashed",
         "reason": "one line: what was expected and what happened",
         "evidence": {"request": {...}, "reply": {...} | null,
                      "motion": {"duration_s", "forward_m", "lateral_m", "turn_deg", "still_at_end", ...} | null,
                      "trajectory": [[t, x, y, yaw], ...],   # <= 400 points, t in sim s since the request
                      ...}},                                 # check-specific extras (reply_after_s, front_distance_m)
        ...
      ],
      "score": 84, "max_score": 100,         # sum of the weights of passed checks / of all checks (advice checks
                                              # weigh 0 unless the suite gives them weight)
      "complete": true,                       # false when the runner was interrupted before every check ran
      "timing": {"wall_s": 41.2, "sim_s": 95.0}
    }

Verdicts: pass / fail when the service answered and the measurement was made (fail: it was measured and is
wrong); error when it could not be measured: the service was missing, the call raised, it did not reply in
time, or the robot could not be prepared. Errors score 0 like failures; the orchestrator may tell them apart.
Crashed (given by the grader, lab_grader.grade): the student's node exited during start-up or the checks; the
reason holds the last line of its traceback. Interference: the submission tampered with what the check measures
(paused physics, teleported the robot, published the simulator's topics; lab_grader.checks.interference): 0 points,
the reason names what it did.
Non-finite floats (a NaN request field) are written as the strings "nan", "inf", "-inf" so the file is strict JSON;
the file is compact (no indentation: a suite's trajectories are thousands of numbers): `python3 -m json.tool` shows
it indented.
"""
import json
import math
import os
import tempfile
from pathlib import Path
from typing import Any, Dict, List, NamedTuple, Optional, Sequence

from lab_grader.errors import GraderError

RESULTS_SCHEMA = "lab_grader.results/1"
PASS = "pass"
FAIL = "fail"
ERROR = "error"
INTERFERENCE = "interference"
CRASHED = "crashed"
VERDICTS = (PASS, FAIL, ERROR, INTERFERENCE, CRASHED)
MAX_REASON_CHARS = 400


class CheckError(GraderError):
    """A check could not be measured (the simulator stopped, the robot would not come to rest): an error verdict
    with this text."""


class InterferenceError(CheckError):
    """The submission tampered with the measurement (lab_grader.checks.interference): an interference verdict
    naming `findings` (what it did, in words)."""

    def __init__(self, findings):
        super().__init__("; ".join(findings))
        self.findings = tuple(findings)


class Interrupted(CheckError):
    """The runner was asked to stop (Ctrl-C, SIGTERM, rospy shutdown): the remaining checks are not run."""


class Verdict(NamedTuple):
    """The outcome of one check: `verdict` is PASS, FAIL or ERROR, `reason` one line, `evidence` JSON-able."""

    verdict: str
    reason: str
    evidence: Dict[str, Any]

    @classmethod
    def passed(cls, reason, evidence=None):
        return cls(PASS, one_line(reason), dict(evidence or {}))

    @classmethod
    def failed(cls, reason, evidence=None):
        return cls(FAIL, one_line(reason), dict(evidence or {}))

    @classmethod
    def errored(cls, reason, evidence=None):
        return cls(ERROR, one_line(reason), dict(evidence or {}))

    @classmethod
    def crashed(cls, reason, evidence=None):
        return cls(CRASHED, one_line(reason), dict(evidence or {}))

    @classmethod
    def interfered(cls, what, evidence=None):
        """`what`: the findings in words (lab_grader.checks.interference.findings)."""
        return cls(INTERFERENCE, one_line("the submission interfered with the measurement: " + "; ".join(what)),
                   dict(evidence or {}, interference=list(what)))


class FoundService(NamedTuple):
    """How a suite's service was found: `found` is the name to call (None: not found), `found_by` "by name",
    "by type" or None, `found_type` the type the server declares, `note` anything a marker should know."""

    expected_name: str
    expected_type: str
    found: Optional[str]
    found_by: Optional[str]
    found_type: Optional[str]
    note: Optional[str]

    def as_json(self):
        return {"expected_type": self.expected_type, "found": self.found, "found_by": self.found_by,
                "found_type": self.found_type, "note": self.note}


class CheckResult(NamedTuple):
    id: str
    title: str
    weight: float
    verdict: Verdict
    kind: str = "required"     # suite_file.REQUIRED or ADVICE

    @property
    def points(self):
        return self.weight if self.verdict.verdict == PASS else 0

    def as_json(self):
        return {"id": self.id, "title": self.title, "kind": self.kind, "weight": self.weight,
                "verdict": self.verdict.verdict,
                "reason": self.verdict.reason, "evidence": self.verdict.evidence}


def one_line(text, limit=MAX_REASON_CHARS):
    """`text` on one line (whitespace runs collapsed), cut to `limit` characters with an ellipsis."""
    flat = " ".join(str(text).split())
    return flat if len(flat) <= limit else flat[:limit - 3] + "..."


def tidy(number):
    """Integral floats as ints (so 16.0 weights read 16), others rounded to 1e-6."""
    number = round(number, 6)
    return int(number) if float(number).is_integer() else number


def score(results: Sequence[CheckResult]):
    """(points, max_points): the weights of passed checks, and of all checks."""
    return tidy(sum(result.points for result in results)), tidy(sum(result.weight for result in results))


def json_safe(value):
    """`value` with tuples as lists, non-string keys as strings and non-finite floats as "nan"/"inf"/"-inf"."""
    if isinstance(value, float) and not math.isfinite(value):
        return "nan" if math.isnan(value) else ("inf" if value > 0 else "-inf")
    if isinstance(value, dict):
        return {str(key): json_safe(item) for key, item in value.items()}
    if isinstance(value, (list, tuple)):
        return [json_safe(item) for item in value]
    if isinstance(value, bytes):
        return list(value)
    return value


def results_document(suite_name: str, services: Dict[str, Dict[str, Any]], results: Sequence[CheckResult],
                     complete: bool = True, timing: Optional[Dict[str, float]] = None) -> Dict[str, Any]:
    """The results file's content (see the module docstring)."""
    points, max_points = score(results)
    return json_safe({
        "schema": RESULTS_SCHEMA,
        "suite": suite_name,
        "services": services,
        "checks": [result.as_json() for result in results],
        "score": points,
        "max_score": max_points,
        "complete": complete,
        "timing": dict(timing or {}),
    })


def write_results(path, document: Dict[str, Any]) -> Path:
    """Write `document` as JSON to `path` atomically: a temporary file in the same folder, then a rename, so a
    reader sees the old file or the whole new one, never half of it. Returns the path."""
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    text = json.dumps(json_safe(document), separators=(",", ":"), allow_nan=False) + "\n"
    handle, temporary = tempfile.mkstemp(prefix="." + path.name + ".", suffix=".tmp", dir=str(path.parent))
    try:
        with os.fdopen(handle, "w", encoding="utf-8") as stream:
            stream.write(text)
            stream.flush()
            os.fsync(stream.fileno())
        os.chmod(temporary, 0o644)
        os.replace(temporary, path)
    except BaseException:
        try:
            os.unlink(temporary)
        except FileNotFoundError:
            pass
        raise
    return path


def summarize_verdicts(results: Sequence[CheckResult]) -> List[str]:
    """One line per check for a terminal: `pass  move_true (16/16): reason`."""
    return ["{:<5} {} ({}/{}): {}".format(result.verdict.verdict, result.id, tidy(result.points),
                                          tidy(result.weight), result.verdict.reason) for result in results]
