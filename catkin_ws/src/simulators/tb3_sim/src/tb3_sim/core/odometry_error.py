"""Opt-in odometry error: /odom and odom->base_footprint follow an integrated, drifting pose instead of the true
one, so SLAM's correction can be tested and shown. Off by default: Gazebo's TurtleBot3 odometry is the model's
true world pose (odometrySource world).

Each step's true motion (in the robot's frame) is replayed from the last odometry pose with its distance scaled
by (1 + scale_error) - wheels a little larger or smaller than the drive assumes - and its heading change
increased by heading_drift rad per metre travelled (a steady turn the robot does not make), plus, if
heading_noise > 0, a seeded random walk of heading_noise rad per square-root metre. A jump of the true pose (a
teleport, reset_world, reset_simulation) is replayed exactly, without error, so odometry keeps the error it had.
"""

import math
from dataclasses import dataclass

import numpy as np

from tb3_sim.core.geometry import Pose2D


@dataclass(frozen=True)
class OdometryErrorModel:
    """scale_error (fraction, e.g. 0.02), heading_drift (rad/m), heading_noise (rad/sqrt(m))."""

    scale_error: float = 0.0
    heading_drift: float = 0.0
    heading_noise: float = 0.0

    @property
    def enabled(self):
        return any((self.scale_error, self.heading_drift, self.heading_noise))


class DriftingOdometry:
    """The odometry pose of one robot under `model`, its noise stream seeded with `seed`."""

    def __init__(self, model, seed):
        self.model = model
        self._seed = seed
        self._rng = np.random.default_rng(seed)
        self._true = None
        self._odom = None
        self._jumped = False

    def pose(self, true_pose):
        """The odometry pose for the robot's current `true_pose` (a Pose2D)."""
        if self._true is None:
            self._true = self._odom = true_pose
            return true_pose
        c, s = math.cos(self._true.yaw), math.sin(self._true.yaw)
        dx, dy = true_pose.x - self._true.x, true_pose.y - self._true.y
        forward, left = c * dx + s * dy, -s * dx + c * dy
        turn = math.atan2(math.sin(true_pose.yaw - self._true.yaw), math.cos(true_pose.yaw - self._true.yaw))
        if not self._jumped:
            distance = math.hypot(forward, left)
            forward, left = forward * (1.0 + self.model.scale_error), left * (1.0 + self.model.scale_error)
            turn += self.model.heading_drift * distance
            if self.model.heading_noise:
                turn += self._rng.normal(0.0, self.model.heading_noise * math.sqrt(distance))
        self._jumped = False
        self._true = true_pose
        x, y = self._odom.compose(forward, left)
        self._odom = Pose2D(x, y, self._odom.yaw + turn)
        return self._odom

    def jumped(self):
        """The true pose jumped (teleport or reset): replay the next change exactly."""
        self._jumped = True

    def restart(self):
        """Sim time went back to 0 (reset_simulation): the noise stream restarts; the jump is replayed exactly."""
        self._rng = np.random.default_rng(self._seed)
        self._jumped = True
