"""The tf2 tutorial's follower controller and its carrot frames, as plain functions.

The follower sees its target at (x, y) in its own frame (metres, x ahead, y left) and steers with the
tutorial's gains: angular.z = 4 * atan2(y, x) (rad/s), linear.x = 0.5 * distance (m/s).
"""
import math
from typing import NamedTuple

ANGULAR_GAIN = 4.0
LINEAR_GAIN = 0.5
FIXED_CARROT_OFFSET_M = (0.0, 2.0)   # the tutorial's carrot1: 2 m to turtle1's left, in turtle1's frame
MOVING_CARROT_RADIUS_M = 10.0        # the tutorial's moving carrot1 circles turtle1 once every 2 s


class Command(NamedTuple):
    linear: float
    angular: float


def follow_command(target_x, target_y):
    """The velocity command that steers toward a target at (target_x, target_y) in the follower's frame."""
    return Command(LINEAR_GAIN * math.hypot(target_x, target_y), ANGULAR_GAIN * math.atan2(target_y, target_x))


def moving_carrot_offset(now_s):
    """carrot1's position in turtle1's frame at time `now_s` (s): (10 sin(pi t), 10 cos(pi t))."""
    phase = now_s * math.pi
    return MOVING_CARROT_RADIUS_M * math.sin(phase), MOVING_CARROT_RADIUS_M * math.cos(phase)


def yaw_quaternion(yaw):
    """(x, y, z, w) of a rotation by `yaw` radians about z."""
    return 0.0, 0.0, math.sin(yaw / 2.0), math.cos(yaw / 2.0)
