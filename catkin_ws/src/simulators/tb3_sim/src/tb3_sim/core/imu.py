"""The IMU as Gazebo's `libgazebo_ros_imu` model plugin reports it (spec §3.3), from ground truth.

Orientation is the absolute world yaw (so it starts at the spawn yaw), angular velocity the world yaw rate, and
linear acceleration the finite difference of the world velocity between two readings, rotated into the body
frame, **without gravity** (≈0 at rest, unlike a real IMU). No noise: the plugin's gaussianNoise is 0.
"""

import math
from dataclasses import dataclass

from tb3_sim.core.geometry import Twist2D


@dataclass(frozen=True)
class ImuReading:
    """yaw (rad, world), yaw_rate (rad/s), accel_x / accel_y (m/s², body frame), time_s (sim seconds)."""

    yaw: float
    yaw_rate: float
    accel_x: float
    accel_y: float
    time_s: float


class Imu:
    """Turns successive ground-truth states into IMU readings; remembers only the previous velocity.

    `max_gap_s`: a reading more than this after the previous one reports zero acceleration, as the first one
    does, because a velocity that old says nothing about the acceleration now (readings stop while nobody
    subscribes to /imu, and start again when someone does).
    """

    def __init__(self, max_gap_s=math.inf):
        self.max_gap_s = max_gap_s
        self.reset()

    def reset(self):
        """Forget the previous reading (call after a teleport or a reset, so no spike is reported)."""
        self._previous = None

    def read(self, now_s, pose, twist_world):
        """Reading at `now_s` for a body at `pose` moving with `twist_world` (world frame).

        The first reading after a reset, one at the same time as the previous, or one more than `max_gap_s`
        after it reports zero acceleration.
        """
        accel = Twist2D()
        if self._previous is not None and 0.0 < now_s - self._previous[0] <= self.max_gap_s:
            then_s, before = self._previous
            dt_s = now_s - then_s
            accel = Twist2D((twist_world.vx - before.vx) / dt_s, (twist_world.vy - before.vy) / dt_s)
        self._previous = (now_s, twist_world)
        body_accel = accel.rotated(-pose.yaw)
        return ImuReading(pose.yaw, twist_world.wz, body_accel.vx, body_accel.vy, now_s)
