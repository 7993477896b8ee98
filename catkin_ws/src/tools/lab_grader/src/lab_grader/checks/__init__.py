"""lab_grader.checks: run a grading suite's checks against a live ROS graph and judge what the robot did.

`motion` (what one call made the robot do, from ground-truth odometry), `fields` (comparing reply and result
fields), `verdicts` (pass/fail/error, scoring and the results file), `service_checks` and `action_checks` (one check
of each kind, judged) and `runner` (a whole suite, and the run_checks command) are plain Python; `context`
(GradingContext) is the only module that talks to ROS, and is imported only when a run starts."""
from lab_grader.checks.motion import MotionSummary, Observation, Sample, summarize
from lab_grader.checks.verdicts import (
    CheckError,
    CheckResult,
    FoundService,
    Interrupted,
    Verdict,
    results_document,
    write_results,
)

__all__ = ["CheckError", "CheckResult", "FoundService", "Interrupted", "MotionSummary", "Observation", "Sample",
           "Verdict", "results_document", "summarize", "write_results"]
