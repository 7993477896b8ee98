"""Validation of the Week 4 service requests: turn a request into a plan, or say exactly what is wrong.

Every check happens before the robot moves, so a rejected request never causes motion.
"""
import math
from typing import NamedTuple

DEFAULT_LINEAR_SPEED_MPS = 0.1
DEFAULT_ANGULAR_SPEED_RADPS = 0.3
MAX_TIMED_MOVE_S = 60
MOVEMENTS = ("fwd", "back", "left", "right")

MAX_APPROACH_VELOCITY_MPS = 0.26   # the Waffle's top speed
MIN_APPROACH_DISTANCE_M = 0.2      # the LiDAR sees nothing closer than 0.12 m, and the body needs room
MAX_APPROACH_DISTANCE_M = 3.5      # the LiDAR's range_max; the distance must be strictly below it


class InvalidRequest(ValueError):
    """A request the server refuses; the text names the field, the value and what is allowed."""


class Motion(NamedTuple):
    """A constant velocity command held for `duration_s` seconds (m/s, rad/s, s)."""

    linear: float
    angular: float
    duration_s: float


def timed_movement(movement_request, duration, linear_speed=DEFAULT_LINEAR_SPEED_MPS,
                   angular_speed=DEFAULT_ANGULAR_SPEED_RADPS):
    """The Motion for a tuos_msgs/TimedMovement request: `fwd`/`back` drive, `left`/`right` turn on the spot.

    The word is matched exactly after trimming surrounding spaces and lower-casing (the course types
    lower-case words; "FWD " is still clearly meant as fwd). Duration is whole seconds, 1..60.
    """
    word = movement_request.strip().lower()
    if word not in MOVEMENTS:
        raise InvalidRequest("movement_request '{}' is not one of {}".format(movement_request, ", ".join(MOVEMENTS)))
    if duration <= 0:
        raise InvalidRequest("duration {} s must be positive".format(duration))
    if duration > MAX_TIMED_MOVE_S:
        raise InvalidRequest("duration {} s is longer than the {} s limit".format(duration, MAX_TIMED_MOVE_S))
    linear = {"fwd": linear_speed, "back": -linear_speed}.get(word, 0.0)
    angular = {"left": angular_speed, "right": -angular_speed}.get(word, 0.0)
    return Motion(linear, angular, float(duration))


class ApproachPlan(NamedTuple):
    """Drive ahead at `velocity` (m/s) until the closest object ahead is `distance` (m) away."""

    distance: float
    velocity: float


def approach(approach_distance, approach_velocity):
    """The ApproachPlan for a tuos_msgs/Approach request, or InvalidRequest naming the bad field."""
    if not math.isfinite(approach_velocity) or not 0.0 < approach_velocity <= MAX_APPROACH_VELOCITY_MPS:
        raise InvalidRequest("approach_velocity {} m/s must be in (0, {}]".format(
            approach_velocity, MAX_APPROACH_VELOCITY_MPS))
    if not math.isfinite(approach_distance) or not (
            MIN_APPROACH_DISTANCE_M <= approach_distance < MAX_APPROACH_DISTANCE_M):
        raise InvalidRequest("approach_distance {} m must be in [{}, {})".format(
            approach_distance, MIN_APPROACH_DISTANCE_M, MAX_APPROACH_DISTANCE_M))
    return ApproachPlan(float(approach_distance), float(approach_velocity))
