"""move_base's default recovery behaviours: two costmap resets and two in-place rotations.

Without a `recovery_behaviors` parameter (turtlebot3 sets none) move_base runs, in order,
conservative_reset (clear_costmap_recovery, reset_distance = conservative_reset_dist), rotate_recovery,
aggressive_reset (reset_distance = 4 x circumscribed_radius, whose default 0.46 makes 1.84 m) and
rotate_recovery again; the rotations are left out when clearing_rotation_allowed is false. The resets clear the
layers named `obstacles`, which turtlebot3's costmaps do not have, so there they clear nothing.
"""
from dataclasses import dataclass

import numpy as np

from ..angles import normalize

CONSERVATIVE_RESET = "conservative_reset"
ROTATE_RECOVERY = "rotate_recovery"
AGGRESSIVE_RESET = "aggressive_reset"
CLEARABLE_LAYERS = ("obstacles",)
DEFAULT_CIRCUMSCRIBED_RADIUS_M = 0.46


@dataclass(frozen=True)
class Recovery:
    """One step of the sequence: its name, and the square (m) a reset keeps (None for a rotation)."""

    name: str
    reset_distance: float = None

    @property
    def rotates(self):
        return self.reset_distance is None

    def clear_message(self):
        return f"Clearing both costmaps outside a square ({self.reset_distance:.2f}m) large centered on the robot."


def default_recoveries(conservative_reset_dist=3.0, clearing_rotation_allowed=True,
                       circumscribed_radius=DEFAULT_CIRCUMSCRIBED_RADIUS_M):
    steps = [Recovery(CONSERVATIVE_RESET, conservative_reset_dist), Recovery(ROTATE_RECOVERY),
             Recovery(AGGRESSIVE_RESET, 4.0 * circumscribed_radius), Recovery(ROTATE_RECOVERY)]
    return [s for s in steps if clearing_rotation_allowed or not s.rotates]


@dataclass(frozen=True)
class RotateParams:
    """rotate_recovery's speeds (TrajectoryPlannerROS defaults: turtlebot3 loads none) in rad/s, rad/s^2."""

    max_rotational_vel: float = 1.0
    min_in_place_rotational_vel: float = 0.4
    acc_lim_th: float = 3.2
    tolerance: float = 0.10
    frequency: float = 20.0


class RotateRecovery:
    """A full counter-clockwise turn from the yaw it starts at: passes the opposite heading, then comes back."""

    def __init__(self, start_yaw, params=RotateParams()):
        self.params = params
        self._start = start_yaw
        self._got_180 = False

    def remaining(self, yaw):
        """Angle (rad) still to turn from `yaw`; 0 once the turn is complete (within tolerance)."""
        if not self._got_180:
            to_180 = abs(float(normalize(yaw - (self._start + np.pi))))
            if to_180 < self.params.tolerance:
                self._got_180 = True
            else:
                return np.pi + to_180
        left = abs(float(normalize(yaw - self._start)))
        return 0.0 if left < self.params.tolerance else left

    def command(self, yaw):
        """The angular velocity (rad/s, > 0) to send at `yaw`, or None when the turn is done."""
        left = self.remaining(yaw)
        if left == 0.0:
            return None
        p = self.params
        return float(np.clip(np.sqrt(2.0 * p.acc_lim_th * left), p.min_in_place_rotational_vel,
                             p.max_rotational_vel))
