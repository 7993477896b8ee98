"""When slam_gmapping sends map -> odom: once per transform_publish_period of sim time, on that period's tick.

gmapping sends it from a thread sleeping on a ros::Rate, which sends one transform per wake-up: a loop that wakes
late sends fewer. In Python the thread also waits for the interpreter lock while a scan is matched or a map
built, and at 8x real time a 50 ms period is 6 ms of wall time: such a loop sent 6 to 19 a second of sim time,
with gaps of up to 1.5 s, on a 2-core machine at load 10. Here the ticks are the multiples of the period on the
sim clock, and a late wake-up sends each tick it slept past, stamped at its own tick (plus tf_delay, as gmapping
stamps into the future): a listener gets 20 transforms per second of sim time, 0.05 s apart, whatever the load.
A wake-up more than MAX_CATCH_UP_S late, or a clock that jumped back (a simulator reset), starts the ticks afresh
from the current one.
"""
import math

MAX_CATCH_UP_S = 1.0
# Slack for a clock reading that is a float sum of periods (0.1 + 0.05 < 0.15): within this of a tick is on it.
TICK_EPSILON = 1e-6


class TransformTicks:
    """The ticks (s of sim time, multiples of `period_s`) at which a transform is due."""

    def __init__(self, period_s):
        if not period_s > 0.0:
            raise ValueError(f"period_s must be > 0, got {period_s!r}")
        self.period_s = period_s
        self._last = None   # index of the last tick handed out

    def due(self, now_s):
        """The ticks up to `now_s` not handed out yet, oldest first (the current tick alone after a jump)."""
        current = math.floor(now_s / self.period_s + TICK_EPSILON)
        if self._last is None or current < self._last or (current - self._last) * self.period_s > MAX_CATCH_UP_S:
            self._last = current - 1
        ticks = [k * self.period_s for k in range(self._last + 1, current + 1)]
        self._last = max(self._last, current)
        return ticks

    def next_s(self, now_s):
        """The next tick after `now_s`."""
        return (math.floor(now_s / self.period_s + TICK_EPSILON) + 1) * self.period_s
