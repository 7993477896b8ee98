"""week6_vision.pillar_search: turn while the colour is out of view, centre it proportionally, stop and report,
pause, then the next colour; give up after a turn and a quarter; done after the last."""
import math

import pytest

from week6_vision.pillar_search import ColourSearch


def test_turns_anticlockwise_until_the_colour_is_in_view_then_centres_it():
    search = ColourSearch(["blue"], turn_speed=0.4, gain=0.5, tolerance=0.02)
    assert search.update(None, 0.0).angular == 0.4
    assert search.update(-0.5, 0.1).angular == pytest.approx(0.25)    # left of the middle: keep turning left
    assert search.update(0.2, 0.2).angular == pytest.approx(-0.1)     # overshot: back to the right
    assert search.update(-1.0, 0.3).angular == pytest.approx(0.4)     # clamped to the turn speed


def test_stops_facing_the_colour_pauses_then_looks_for_the_next():
    search = ColourSearch(["blue", "red"], pause_s=2.0, tolerance=0.02)
    search.update(None, 0.0)
    step = search.update(0.01, 1.0)
    assert (step.angular, step.event, step.done) == (0.0, "facing blue", False)
    assert search.update(0.5, 2.9) == (0.0, None, False)   # still pausing, whatever it sees
    assert search.target == "blue"
    assert search.update(None, 3.0) == (0.0, None, False)
    assert search.target == "red"
    assert search.update(None, 3.1).angular == 0.4


def test_the_last_colour_ends_the_search():
    search = ColourSearch(["red"], pause_s=1.0)
    search.update(0.0, 0.0)
    assert search.update(0.0, 1.0).done
    assert search.target is None
    assert search.update(0.3, 2.0) == (0.0, None, False)


def test_a_colour_never_in_view_is_given_up_after_a_turn_and_a_quarter():
    search = ColourSearch(["green", "blue"], turn_speed=0.5)
    give_up_s = 1.25 * 2 * math.pi / 0.5
    search.update(None, 0.0)
    assert search.update(None, give_up_s - 0.1).angular == 0.5
    step = search.update(None, give_up_s + 0.1)
    assert (step.event, step.done, search.target) == ("green not found", False, "blue")
