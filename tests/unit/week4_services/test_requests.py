"""Week 4 request validation: valid requests become motion plans, everything else a reason and no motion."""
import math

import pytest

from week4_services.requests import InvalidRequest, Motion, approach, timed_movement


@pytest.mark.parametrize("word, expected", [
    ("fwd", Motion(0.1, 0.0, 2.0)), ("back", Motion(-0.1, 0.0, 2.0)),
    ("left", Motion(0.0, 0.3, 2.0)), ("right", Motion(0.0, -0.3, 2.0)), (" FWD ", Motion(0.1, 0.0, 2.0)),
])
def test_timed_movements(word, expected):
    assert timed_movement(word, 2) == expected


def test_timed_movement_speeds_come_from_the_caller():
    assert timed_movement("left", 3, linear_speed=0.2, angular_speed=0.5) == Motion(0.0, 0.5, 3.0)


@pytest.mark.parametrize("word, duration, reason", [
    ("forward", 2, "not one of fwd, back, left, right"),
    ("", 2, "not one of"),
    ("fwd", 0, "must be positive"),
    ("back", -3, "must be positive"),
    ("left", 61, "longer than the 60 s limit"),
    ("right", 2 ** 31 - 1, "longer than the 60 s limit"),
])
def test_bad_timed_movements_name_the_problem(word, duration, reason):
    with pytest.raises(InvalidRequest, match=reason):
        timed_movement(word, duration)


def test_valid_approach():
    plan = approach(0.4, 0.1)
    assert (plan.distance, plan.velocity) == (0.4, 0.1)


@pytest.mark.parametrize("distance, velocity, reason", [
    (0.4, 0.0, "approach_velocity 0.0"), (0.4, -0.1, "approach_velocity"), (0.4, 0.27, r"must be in \(0, 0.26\]"),
    (0.4, math.nan, "approach_velocity nan"), (0.4, math.inf, "approach_velocity inf"),
    (0.19, 0.1, r"approach_distance 0.19 m must be in \[0.2, 3.5\)"), (3.5, 0.1, "approach_distance 3.5"),
    (math.nan, 0.1, "approach_distance nan"), (-1.0, 0.1, "approach_distance"),
])
def test_bad_approach_names_the_field(distance, velocity, reason):
    with pytest.raises(InvalidRequest, match=reason):
        approach(distance, velocity)
