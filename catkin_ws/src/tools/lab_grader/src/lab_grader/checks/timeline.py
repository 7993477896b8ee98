"""Where one check's wall time goes, phase by phase (plain Python, no ROS).

A check is mostly waiting: for the simulator to hear the student's /cmd_vel publisher, for the reset, for the robot
to rest, for the reply, for the settle window after it. The grading context laps each phase as it ends
(`lap("reply")`); the check runner prints the laps after the check's verdict line, so a checks log shows which
waits are motion in sim time (they shrink at a higher real-time factor) and which are fixed wall-clock costs:

    [1/2] pass  move_true (16/16): replied ...
          1.9 s: heard 0.00, reset 0.01, rest 0.21, reply 1.18, tail 0.51

Phase names are the context's (lab_grader.checks.context documents them); the clock is injected (wall seconds,
time.monotonic by default) so the laps are unit-tested without waiting.
"""
import time
from typing import Callable, List, Tuple


class Timeline:
    """The laps of the current check since `begin()`: (phase, wall seconds since the previous lap)."""

    def __init__(self, clock: Callable[[], float] = time.monotonic):
        self._clock = clock
        self._last = clock()
        self.laps: List[Tuple[str, float]] = []

    def begin(self) -> None:
        self._last = self._clock()
        self.laps = []

    def lap(self, phase: str) -> None:
        now = self._clock()
        self.laps.append((phase, now - self._last))
        self._last = now

    def words(self) -> str:
        """'1.9 s: heard 0.00, reset 0.01, ...' (the total, then each lap), or '' before any lap."""
        if not self.laps:
            return ""
        return "{:.1f} s: {}".format(sum(seconds for _, seconds in self.laps),
                                     ", ".join("{} {:.2f}".format(phase, seconds) for phase, seconds in self.laps))
