"""Shared request checks: durations and speeds, with the field named in every refusal."""
import math

import pytest

from tb3_client.motion import InvalidRequest, check_duration, check_speed


@pytest.mark.parametrize("seconds", [1, 2.5, 60])
def test_durations_in_range(seconds):
    assert check_duration("time", seconds) == float(seconds)


@pytest.mark.parametrize("seconds, reason", [(0, "time 0 s must be positive"), (-2, "must be positive"),
                                             (math.nan, "time nan is not a finite"), (61, "longer than the 60 s"),
                                             (math.inf, "time inf is not a finite number of seconds")])
def test_bad_durations(seconds, reason):
    with pytest.raises(InvalidRequest, match=reason):
        check_duration("time", seconds)


@pytest.mark.parametrize("value", [0.0, -0.1, 1.83, math.nan, math.inf])
def test_bad_speeds_name_the_field_and_limit(value):
    with pytest.raises(InvalidRequest, match=r"angular_velocity .* must be in \(0, 1.82\]"):
        check_speed("angular_velocity", value, 1.82)


def test_speed_at_the_limit_is_allowed():
    assert check_speed("velocity", 0.26, 0.26) == 0.26
