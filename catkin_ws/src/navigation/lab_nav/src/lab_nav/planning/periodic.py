"""move_base's periodic work (costmap updates and publishing, the control cycle) run from one thread.

Why one thread: under /use_sim_time every thread that sleeps in rospy (a rospy.Timer, a rospy.Rate) is woken by
each /clock message (100 Hz of sim time, 1000 a second at a real-time factor of 10) to check whether its time has
come. move_base had five such sleepers (an update and a publish timer per costmap, the control loop); one loop that
sleeps until the earliest task is due is woken as often as one of them.

Each task keeps its own period, as a rospy.Timer does: the next run is one period after the last one was due, and
a task that fell more than a period behind (a slow machine, a jump of the clock) is rescheduled a period from now
instead of running the missed periods back to back. Time going backwards (a simulator reset) restarts every task
from the new time. Times are seconds of whatever clock the caller passes in (sim time in move_base).
"""
import math

DUE_TOLERANCE_S = 1e-6
"""A task is due this close before its time. Sums of periods in float seconds land a few 1e-15 s past a clock
stamp (the simulator's /clock steps 0.01 s), and a sleep that short ends at once: without the tolerance the loop
spun until the next /clock message, most of a core at real time."""


class PeriodicTasks:
    """Callables run at fixed periods by `run_due(now)`; `next_due()` says when to call it again."""

    def __init__(self):
        self._tasks = []   # [period s, next due s or None (from the first run_due on), callable, first run delayed]
        self._last_now = None

    def add(self, period_s, task, first_after_period=False):
        """Run `task()` every `period_s` seconds (> 0), first at the next run_due, or with `first_after_period` a
        period after it (as a rospy.Timer first fires a period after it was made)."""
        if not period_s > 0.0:
            raise ValueError(f"a periodic task needs a period above 0 s, got {period_s!r}")
        self._tasks.append([float(period_s), None, task, first_after_period])

    def run_due(self, now):
        """Run every task that is due at `now` (in the order they were added) and schedule its next run."""
        if self._last_now is not None and now < self._last_now:
            for entry in self._tasks:
                entry[1] = None
        self._last_now = now
        for entry in self._tasks:
            period, due, task, first_after_period = entry
            if due is None and first_after_period:
                entry[1] = now + period
                continue
            if due is not None and now < due - DUE_TOLERANCE_S:
                continue
            entry[1] = now + period if due is None or now - due >= period else due + period
            task()

    def next_due(self):
        """The earliest time a task is due (inf without tasks)."""
        return min((due if due is not None else -math.inf for _, due, _, _ in self._tasks), default=math.inf)
