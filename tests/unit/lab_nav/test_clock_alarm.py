"""The alarm a periodic thread sleeps on: woken when the fed clock reaches its deadline or goes back, not per tick."""
import threading
import time

import pytest

from lab_nav.clock_alarm import Alarm, TimeMovedBackwards


class FedClock:
    """A clock the test advances; each reading is ticked into the alarm after it is set, as /clock's callbacks
    run in rospy (its time first, the alarm second)."""

    def __init__(self, alarm, start=0.0):
        self.alarm, self.now = alarm, start

    def set(self, now):
        self.now = now
        self.alarm.tick(now)


def _sleeper(alarm, clock, due, recheck_s=5.0, stopped=lambda: False):
    """Start a thread sleeping until `due`; returns (thread, outcome dict with its end and wake count)."""
    outcome = {"wakes": 0}
    real_wait = alarm._event.wait

    def counting_wait(timeout):
        outcome["wakes"] += 1
        return real_wait(timeout)

    alarm._event.wait = counting_wait

    def run():
        try:
            alarm.sleep_until(due, lambda: clock.now, stopped, recheck_s)
            outcome["ended"] = clock.now
        except TimeMovedBackwards as error:
            outcome["backwards"] = error.args[0]

    thread = threading.Thread(target=run, daemon=True)
    thread.start()
    return thread, outcome


def _settle():
    time.sleep(0.05)


def test_the_sleeper_wakes_once_when_the_deadline_is_reached_not_at_each_tick():
    alarm = Alarm()
    clock = FedClock(alarm)
    thread, outcome = _sleeper(alarm, clock, due=0.1)
    _settle()
    for k in range(1, 10):   # 0.01 ... 0.09 s: before the deadline
        clock.set(k * 0.01)
    _settle()
    assert thread.is_alive() and outcome["wakes"] == 1   # the first wait, never woken since
    clock.set(0.1 - 1e-12)   # a sum of periods a hair past the tick counts as reached
    thread.join(1.0)
    assert not thread.is_alive() and outcome["ended"] == pytest.approx(0.1)
    assert outcome["wakes"] == 1


def test_a_deadline_already_past_returns_at_once():
    alarm = Alarm()
    clock = FedClock(alarm, start=2.0)
    thread, outcome = _sleeper(alarm, clock, due=1.5)
    thread.join(1.0)
    assert outcome == {"wakes": 0, "ended": 2.0}


def test_time_going_back_wakes_the_sleeper_with_the_jump():
    alarm = Alarm()
    clock = FedClock(alarm, start=5.0)
    alarm.tick(5.0)
    thread, outcome = _sleeper(alarm, clock, due=6.0)
    _settle()
    clock.set(1.0)   # a simulator reset
    thread.join(1.0)
    assert outcome["backwards"] == pytest.approx(4.0)


def test_a_paused_clock_still_lets_the_sleeper_see_a_stop_after_the_recheck_interval():
    alarm = Alarm()
    clock = FedClock(alarm)
    stop = threading.Event()
    thread, outcome = _sleeper(alarm, clock, due=1.0, recheck_s=0.02, stopped=stop.is_set)
    _settle()
    stop.set()   # no tick comes
    thread.join(1.0)
    assert not thread.is_alive() and outcome["ended"] == 0.0


def test_ticks_without_a_sleeper_do_nothing_and_a_later_sleep_is_not_woken_by_them():
    alarm = Alarm()
    clock = FedClock(alarm)
    for k in range(1, 50):
        clock.set(k * 0.01)
    thread, outcome = _sleeper(alarm, clock, due=1.0)
    _settle()
    assert thread.is_alive()
    clock.set(1.0)
    thread.join(1.0)
    assert outcome["ended"] == 1.0 and outcome["wakes"] == 1
