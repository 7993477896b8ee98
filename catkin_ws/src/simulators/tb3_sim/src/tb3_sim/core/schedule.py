"""A drift-free periodic schedule in simulated time, for anything that runs at its own rate.

Gazebo plugins run on every physics step and act when their period has elapsed; this does the same as a pure
function of the `now` it is given, so 30 Hz on a 5 ms physics step fires at 35, 70, 100, 135 ... ms and averages
exactly 30 Hz instead of drifting to 28.6 Hz.
"""

# Slack for float sums of periods like 1/30: a deadline within this of `now` counts as reached.
TIME_EPSILON_S = 1e-9


class PeriodicSchedule:
    """Says when a task running at `rate_hz` (simulated time) is due.

    A rate of 0 or `math.inf` means "every time you ask". The first deadline is one period after `start_s`.
    """

    def __init__(self, rate_hz, start_s=0.0):
        if not rate_hz >= 0:
            raise ValueError(f"rate_hz must be >= 0, got {rate_hz!r}")
        self.period_s = 0.0 if rate_hz in (0, float("inf")) else 1.0 / rate_hz
        self.reset(start_s)

    def reset(self, now_s):
        """Restart the schedule so the next deadline is one period after `now_s` (e.g. after a clock jump)."""
        self.next_due_s = now_s + self.period_s

    def due(self, now_s):
        """True (and the deadline moves on by one period) if `now_s` has reached the deadline.

        If `now_s` is more than a period late, the schedule re-bases on `now_s` rather than firing a burst.
        """
        if now_s + TIME_EPSILON_S < self.next_due_s:
            return False
        self.next_due_s += self.period_s
        if self.next_due_s + TIME_EPSILON_S <= now_s:
            self.next_due_s = now_s + self.period_s
        return True
