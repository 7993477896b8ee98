"""Holding a real-time factor: how long to sleep in wall time after each physics step.

Physics always advances in fixed simulated steps; the pacer only decides how long the loop waits between them.
It anchors a (sim, wall) pair and aims for `sim - sim_anchor == factor * (wall - wall_anchor)`. When the loop is
late by more than `max_lag_s` wall seconds (a slow machine, a long service call, a debugger) it re-anchors at the
present instead of bursting through the backlog, so sim time never races to catch up. Sleeps shorter than
`min_sleep_s` are skipped and carried over, because the OS cannot sleep that briefly with any accuracy. No wait
is longer than `max_sleep_s`: the caller sleeps, then asks again (`delay` is the rest of the wait), so a loop
paced very slowly still re-checks shutdown, pause and new pacing at least that often.
All times are plain seconds given by the caller (sim from the world, wall from a monotonic clock): no clock here.
"""

# Defaults: re-anchor after 50 ms behind; do not sleep for less than 1 ms (sleep overshoots by ~0.1 ms), nor for
# more than 100 ms at a time.
MAX_LAG_S = 0.05
MIN_SLEEP_S = 0.001
MAX_SLEEP_S = 0.1


class Pacer:
    """Wall-clock pacing of simulated time at `real_time_factor` (> 0; 0 = as fast as possible, never sleeps)."""

    def __init__(self, real_time_factor, max_lag_s=MAX_LAG_S, min_sleep_s=MIN_SLEEP_S, max_sleep_s=MAX_SLEEP_S):
        if not real_time_factor >= 0:
            raise ValueError(f"real_time_factor must be >= 0, got {real_time_factor!r}")
        self.real_time_factor = float(real_time_factor)
        self.max_lag_s = max_lag_s
        self.min_sleep_s = min_sleep_s
        self.max_sleep_s = max_sleep_s
        self._anchor = None

    def restart(self, sim_s, wall_s):
        """Anchor at (sim_s, wall_s): after a pause, a reset of sim time, or at start."""
        self._anchor = (sim_s, wall_s)

    def delay(self, sim_s, wall_s):
        """Wall seconds to sleep now that simulated time has reached `sim_s` at wall time `wall_s` (>= 0, at most
        `max_sleep_s`; after that sleep, ask again with the same `sim_s` until it answers 0)."""
        if self.real_time_factor == 0:
            return 0.0
        if self._anchor is None or sim_s < self._anchor[0]:
            self.restart(sim_s, wall_s)
            return 0.0
        sim_anchor, wall_anchor = self._anchor
        ahead_s = wall_anchor + (sim_s - sim_anchor) / self.real_time_factor - wall_s
        if ahead_s < -self.max_lag_s:
            self.restart(sim_s, wall_s)
            return 0.0
        return min(ahead_s, self.max_sleep_s) if ahead_s >= self.min_sleep_s else 0.0
