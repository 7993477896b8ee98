"""Planar poses and twists, and the few frame conversions the simulator and the ROS layer share.

Conventions: metres, radians, yaw measured CCW from +x, angles wrapped to (-pi, pi].
"""

import math
from typing import NamedTuple


class Pose2D(NamedTuple):
    """Planar pose: position (x, y) in metres and heading yaw in radians, in the frame the caller names."""

    x: float = 0.0
    y: float = 0.0
    yaw: float = 0.0

    def compose(self, local_x, local_y):
        """The point (local_x, local_y), given in this pose's frame, expressed in the parent frame."""
        c, s = math.cos(self.yaw), math.sin(self.yaw)
        return self.x + c * local_x - s * local_y, self.y + s * local_x + c * local_y


class Twist2D(NamedTuple):
    """Planar velocity: linear (vx, vy) in m/s and yaw rate wz in rad/s, in the frame the caller names."""

    vx: float = 0.0
    vy: float = 0.0
    wz: float = 0.0

    def rotated(self, angle):
        """The same twist with its linear part rotated by `angle` rad (wz is frame-independent in 2D)."""
        c, s = math.cos(angle), math.sin(angle)
        return Twist2D(c * self.vx - s * self.vy, s * self.vx + c * self.vy, self.wz)


def wrap_angle(angle):
    """`angle` in radians wrapped to (-pi, pi]."""
    wrapped = math.atan2(math.sin(angle), math.cos(angle))
    return math.pi if wrapped == -math.pi else wrapped


def yaw_to_quaternion(yaw):
    """Quaternion (x, y, z, w) of a pure rotation by `yaw` rad about z."""
    return 0.0, 0.0, math.sin(yaw / 2.0), math.cos(yaw / 2.0)


def quaternion_to_yaw(x, y, z, w):
    """Yaw in radians of a quaternion (x, y, z, w); it need not be normalised. Roll and pitch are dropped."""
    return math.atan2(2.0 * (w * z + x * y), 1.0 - 2.0 * (y * y + z * z))
