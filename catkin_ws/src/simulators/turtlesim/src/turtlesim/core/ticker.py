"""Headless update timer: call a tick function every 16 ms of wall-clock time (no Qt, no ROS).

It stands in for the original's QTimer when there is no window. Like a QTimer it keeps a fixed
schedule (no drift) and does not make up for ticks it missed: when it falls more than one
interval behind, the schedule restarts from now, so the turtles move more slowly in wall time,
as the original's do when its ticks come late. /use_sim_time plays no part.
"""
import time


def run_ticks(tick, wait, interval_s, clock=time.monotonic):
    """Call `tick()` every `interval_s` seconds until it returns False or a wait is interrupted.

    Args:
        tick: callable() -> bool, False to stop.
        wait: callable(seconds) -> bool, sleeps up to `seconds` and returns True when asked to
            stop (threading.Event.wait does both).
        interval_s: the period in seconds.
        clock: monotonic seconds, injectable for tests.
    """
    next_time = clock() + interval_s
    while True:
        delay = next_time - clock()
        if delay > 0 and wait(delay):
            return
        if not tick():
            return
        next_time += interval_s
        if clock() - next_time > interval_s:
            next_time = clock() + interval_s
