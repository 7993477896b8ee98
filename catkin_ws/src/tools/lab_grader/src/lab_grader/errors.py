"""The one exception root of lab_grader's logic, so a command-line front end can turn every expected failure
(a bad submission, a sandbox that cannot be set up) into one clear line instead of a traceback."""


class GraderError(Exception):
    """Base of every error lab_grader raises on purpose; its message is meant for the instructor."""


class SandboxError(GraderError):
    """A sandbox could not be set up or cleaned up (a missing tool, a busy slot, a process that would not die)."""
