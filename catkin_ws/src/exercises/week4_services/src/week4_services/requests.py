"""Validation of the Week 4 service requests: turn a request into a plan, or say exactly what is wrong
(InvalidRequest, re-exported from tb3_client.motion).

Every check happens before the robot moves, so a rejected request never causes motion.
"""
import math
from typing import NamedTuple

from tb3_client.motion import MAX_LINEAR_MPS, InvalidRequest, Motion, check_duration, check_speed

DEFAULT_LINEAR_SPEED_MPS = 0.1
DEFAULT_ANGULAR_SPEED_RADPS = 0.3
MOVEMENTS = ("fwd", "back", "left", "right")

MIN_APPROACH_DISTANCE_M = 0.2      # the LiDAR sees nothing closer than 0.12 m, and the body needs room
MAX_APPROACH_DISTANCE_M = 3.5      # the LiDAR's range_max; the distance must be strictly below it


def timed_movement(movement_request, duration, linear_speed=DEFAULT_LINEAR_SPEED_MPS,
                   angular_speed=DEFAULT_ANGULAR_SPEED_RADPS):
    """The Motion for a tuos_msgs/TimedMovement request: `fwd`/`back` drive, `left`/`right` turn on the spot.

    The word is matched exactly after trimming surrounding spaces and lower-casing (the course types
    lower-case words; "FWD " is still clearly meant as fwd). Duration is whole seconds, 1..60.
    """
    word = movement_request.strip().lower()
    if word not in MOVEMENTS:
        raise InvalidRequest("movement_request '{}' is not one of {}".format(movement_request, ", ".join(MOVEMENTS)))
    duration_s = check_duration("duration", duration)
    linear = {"fwd": linear_speed, "back": -linear_speed}.get(word, 0.0)
    angular = {"left": angular_speed, "right": -angular_speed}.get(word, 0.0)
    return Motion(linear, angular, duration_s)


class ApproachPlan(NamedTuple):
    """Drive ahead at `velocity` (m/s) until the closest object ahead is `distance` (m) away."""

    distance: float
    velocity: float


def approach(approach_distance, approach_velocity):
    """The ApproachPlan for a tuos_msgs/Approach request, or InvalidRequest naming the bad field."""
    velocity = check_speed("approach_velocity", approach_velocity, MAX_LINEAR_MPS)
    if not math.isfinite(approach_distance) or not (
            MIN_APPROACH_DISTANCE_M <= approach_distance < MAX_APPROACH_DISTANCE_M):
        raise InvalidRequest("approach_distance {} m must be in [{}, {})".format(
            approach_distance, MIN_APPROACH_DISTANCE_M, MAX_APPROACH_DISTANCE_M))
    return ApproachPlan(float(approach_distance), velocity)
