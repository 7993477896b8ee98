"""A check's timeline: laps of wall time per phase, in words for the checks log and as data."""
import pytest

from lab_grader.checks.timeline import Timeline


class Clock:
    def __init__(self):
        self.now = 100.0

    def __call__(self):
        return self.now


def test_laps_are_the_time_since_the_previous_lap_from_begin():
    clock = Clock()
    timeline = Timeline(clock)
    clock.now += 50.0                       # before begin: not counted
    timeline.begin()
    for phase, seconds in (("heard", 0.004), ("reset", 0.02), ("rest", 0.25), ("reply", 5.1), ("tail", 1.0)):
        clock.now += seconds
        timeline.lap(phase)
    assert timeline.words() == "6.4 s: heard 0.00, reset 0.02, rest 0.25, reply 5.10, tail 1.00"
    assert [phase for phase, _ in timeline.laps] == ["heard", "reset", "rest", "reply", "tail"]
    assert [seconds for _, seconds in timeline.laps] == pytest.approx([0.004, 0.02, 0.25, 5.1, 1.0])


def test_begin_forgets_the_previous_check_and_a_phase_lapped_twice_is_listed_twice():
    clock = Clock()
    timeline = Timeline(clock)
    clock.now += 1.0
    timeline.lap("reply")
    timeline.begin()
    assert timeline.words() == "" and timeline.laps == []
    for seconds in (0.5, 0.25):
        clock.now += seconds
        timeline.lap("rest")
    assert timeline.words() == "0.8 s: rest 0.50, rest 0.25"
