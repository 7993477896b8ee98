"""move_base's periodic tasks run from one thread: each at its own period, late ones rescheduled, not repeated."""
import math

import pytest

from lab_nav.planning.periodic import PeriodicTasks


def _recorder(tasks, period, name, log):
    tasks.add(period, lambda: log.append(name))


def test_tasks_run_at_their_own_periods_in_the_order_added():
    tasks, log = PeriodicTasks(), []
    _recorder(tasks, 0.1, "update", log)
    _recorder(tasks, 0.2, "plan", log)
    runs = []
    for k in range(5):   # 0.0, 0.1, ..., 0.4 s
        del log[:]
        tasks.run_due(k * 0.1)
        runs.append(tuple(log))
    assert runs == [("update", "plan"), ("update",), ("update", "plan"), ("update",), ("update", "plan")]
    assert tasks.next_due() == pytest.approx(0.5)


def test_nothing_runs_before_it_is_due_and_a_late_task_runs_once_then_a_period_later():
    tasks, log = PeriodicTasks(), []
    _recorder(tasks, 0.1, "control", log)
    tasks.run_due(0.0)
    tasks.run_due(0.05)
    assert log == ["control"]
    tasks.run_due(0.35)   # three periods missed: one run, not three
    assert log == ["control"] * 2
    assert tasks.next_due() == pytest.approx(0.45)


def test_a_slightly_late_run_keeps_the_schedule():
    tasks, log = PeriodicTasks(), []
    _recorder(tasks, 0.1, "control", log)
    tasks.run_due(0.0)
    tasks.run_due(0.13)
    assert tasks.next_due() == pytest.approx(0.2)


def test_time_going_backwards_restarts_every_task():
    tasks, log = PeriodicTasks(), []
    _recorder(tasks, 1.0, "publish", log)
    tasks.run_due(50.0)
    tasks.run_due(0.2)   # the simulator was reset
    assert log == ["publish"] * 2
    assert tasks.next_due() == pytest.approx(1.2)


def test_without_tasks_nothing_is_due_and_a_period_must_be_positive():
    tasks = PeriodicTasks()
    assert tasks.next_due() == math.inf
    with pytest.raises(ValueError, match="period above 0 s, got 0"):
        tasks.add(0, lambda: None)


def test_a_task_due_a_rounding_error_after_the_clock_runs_now():
    """0.2 + 0.1 is 0.30000000000000004: at a clock of 0.3 the task is due, not 4e-17 s later (a loop that slept
    that long woke at once and spun until the next clock message)."""
    tasks, log = PeriodicTasks(), []
    _recorder(tasks, 0.1, "control", log)
    for now in (0.0, 0.1, 0.2, 0.3):
        tasks.run_due(now)
    assert len(log) == 4


def test_a_task_added_to_run_after_its_period_first_runs_a_period_after_the_first_call_as_a_rospy_timer():
    tasks, log = PeriodicTasks(), []
    tasks.add(15.0, lambda: log.append("check"), first_after_period=True)
    _recorder(tasks, 5.0, "update", log)
    for now in (100.0, 105.0, 110.0, 115.0, 130.0):
        tasks.run_due(now)
    assert log == ["update", "update", "update", "check", "update", "check", "update"]
    tasks.run_due(1.0)   # time went back: the delay starts again
    assert log[-1] == "update" and tasks.next_due() == pytest.approx(6.0)
