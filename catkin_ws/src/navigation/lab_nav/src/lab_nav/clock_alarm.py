"""A sleep until a time of a clock fed from outside, woken once when the time comes rather than at every tick.

Why: rospy.sleep under /use_sim_time waits on the one condition rospy notifies at every /clock message (100 per sim
second from the simulator, 1000 a wall second at a real-time factor of 10), so a sleeping thread wakes, takes the
GIL, compares the time with its deadline and sleeps again at every tick. An Alarm is fed the clock's readings by
whoever receives them (nav_ros.sim_clock: a second callback on /clock) and wakes its sleeper only when a reading
reaches the deadline or goes backwards (a simulator reset), so a thread with a 10 Hz task wakes 10 times a sim
second, not 100. Times are float seconds of that clock; nothing here knows ROS.
"""
import math
import threading

from .planning.periodic import DUE_TOLERANCE_S  # the alarm rings when PeriodicTasks would run the task


class TimeMovedBackwards(Exception):
    """The clock went back while a sleeper waited (rospy.sleep raises ROSTimeMovedBackwardsException then)."""


class Alarm:
    """One sleeper at a time waits in `sleep_until`; any thread calls `tick(now)` with each clock reading."""

    def __init__(self):
        self._event = threading.Event()
        self._due = math.inf
        self._last = -math.inf

    def tick(self, now):
        """A new reading of the clock: wake the sleeper when it reaches the deadline or goes backwards."""
        if now >= self._due - DUE_TOLERANCE_S or now < self._last:
            self._event.set()
        self._last = now

    def sleep_until(self, due, now, stopped, recheck_s):
        """Return once now() >= due (within DUE_TOLERANCE_S) or stopped() is true; raise TimeMovedBackwards when
        now() goes below its value at the start. `now` reads the clock that feeds `tick`, after it has taken the
        reading being ticked; `recheck_s` is the wall time after which the sleeper looks at now() and stopped()
        even without a tick (a paused clock, a shutdown)."""
        start = now()
        self._event.clear()
        self._due = due   # set before the first look, so a tick between the look and the wait still wakes it
        try:
            while not stopped():
                current = now()
                if current < start:
                    raise TimeMovedBackwards(start - current)
                if current >= due - DUE_TOLERANCE_S:
                    return
                self._event.wait(recheck_s)
                self._event.clear()
        finally:
            self._due = math.inf
