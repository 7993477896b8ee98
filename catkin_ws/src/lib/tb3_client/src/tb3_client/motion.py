"""Motion requests as plain data: a velocity held for a time, the Waffle's speed limits, and the one error
type every course server uses to refuse a request (plain Python)."""
import math
from typing import NamedTuple

MAX_LINEAR_MPS = 0.26      # TurtleBot3 Waffle top speed (ROBOTIS specification, turtlebot3_teleop)
MAX_ANGULAR_RADPS = 1.82
MAX_MOTION_S = 60          # longer requests are refused as typos rather than driven blind


class InvalidRequest(ValueError):
    """A request the server refuses; the text names the field, the value and what is allowed."""


class Motion(NamedTuple):
    """A constant velocity command held for `duration_s` seconds (m/s, rad/s, s)."""

    linear: float
    angular: float
    duration_s: float


def check_duration(name, seconds):
    """`seconds` as a float if it is in (0, MAX_MOTION_S], else InvalidRequest naming field `name`."""
    if not math.isfinite(seconds):
        raise InvalidRequest("{} {} is not a finite number of seconds".format(name, seconds))
    if seconds <= 0:
        raise InvalidRequest("{} {} s must be positive".format(name, seconds))
    if seconds > MAX_MOTION_S:
        raise InvalidRequest("{} {} s is longer than the {} s limit".format(name, seconds, MAX_MOTION_S))
    return float(seconds)


def check_speed(name, value, limit):
    """`value` as a float if it is in (0, limit], else InvalidRequest naming field `name`."""
    if not math.isfinite(value) or not 0.0 < value <= limit:
        raise InvalidRequest("{} {} must be in (0, {}]".format(name, value, limit))
    return float(value)
