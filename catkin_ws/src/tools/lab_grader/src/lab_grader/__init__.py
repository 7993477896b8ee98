"""lab_grader: grade a class's ROS exercise packages safely and in parallel.

Layers so far: `submissions` (find and safely extract what students handed in) and `sandbox` (run a submission's
untrusted processes isolated from the network, the grader and each other)."""
from lab_grader.errors import GraderError
from lab_grader.sandbox import Limits, SandboxError, SubmissionSandbox
from lab_grader.sandbox_process import RunResult, SandboxProcess, StopReason
from lab_grader.submissions import (
    ArchiveLimits,
    Submission,
    SubmissionError,
    SubmissionScan,
    find_submissions,
    load_submission,
)

__all__ = [
    "ArchiveLimits", "GraderError", "Limits", "RunResult", "SandboxError", "SandboxProcess", "StopReason",
    "Submission", "SubmissionError", "SubmissionSandbox", "SubmissionScan", "find_submissions", "load_submission",
]
