"""Gazebo's differential-drive plugin (`libgazebo_ros_diff_drive`, noetic) as configured for the Waffle.

Kept on purpose from the original (spec §3.1):
- no command timeout: the last command is held until a new one arrives or the drive is reset;
- no clamping to the robot's limits (optional `limits` for exercises that want the vendor limits);
- per-wheel rim-speed targets v -/+ w * separation / 2 (left, right), approached at 30 Hz (sim time) by at most
  `acceleration_mps2 * dt` per update; if either wheel is within 0.01 m/s of its target both are set directly.
The simulator applies the resulting (v, w) to the robot body as a velocity, like flatland; the wheels slip
rather than stall when the body is blocked, so the wheel angles keep turning at the commanded speed.
"""

import math

from tb3_sim.core.errors import InvalidCommandError
from tb3_sim.core.schedule import PeriodicSchedule
from tb3_sim.core.turtlebot3 import WAFFLE, WHEEL_RADIUS_M

DRIVE_UPDATE_RATE_HZ = 30.0
WHEEL_ACCELERATION_MPS2 = 1.0
WHEEL_SPEED_TOLERANCE_MPS = 0.01

# Sanity limits, not a clamp: about 40x and 16x the Waffle's limits. Anything beyond is a bug in the sender
# (or a unit mistake) and is refused rather than flung through the physics.
COMMAND_LIMIT_LINEAR_MPS = 10.0
COMMAND_LIMIT_ANGULAR_RADPS = 30.0


def validate_command(linear_mps, angular_radps):
    """None if (linear_mps, angular_radps) is an acceptable command, otherwise the reason as a sentence.

    Acceptable: finite numbers with |linear| <= COMMAND_LIMIT_LINEAR_MPS m/s and |angular| <=
    COMMAND_LIMIT_ANGULAR_RADPS rad/s. The ROS node logs the reason (throttled) and ignores the message.
    """
    for label, value, limit, unit in (("linear.x", linear_mps, COMMAND_LIMIT_LINEAR_MPS, "m/s"),
                                      ("angular.z", angular_radps, COMMAND_LIMIT_ANGULAR_RADPS, "rad/s")):
        if not math.isfinite(value):
            return f"{label} is {value}; expected a finite number"
        if abs(value) > limit:
            return f"{label} = {value} {unit} is beyond the sanity limit of ±{limit} {unit}"
    return None


class DiffDrive:
    """Rim-speed ramp and wheel odometry of a two-wheeled robot; no physics, no clock of its own.

    Units: m/s at the wheel rim, rad/s, rad. Call `update(now_s)` before every physics step (it acts at
    `update_rate_hz`) and `advance_wheels(dt_s)` after it; read `velocity` to drive the body.
    `limits` (max linear m/s, max angular rad/s) clamps commands, None (Gazebo's way, the default) does not.
    """

    def __init__(self, wheel_separation_m=WAFFLE.wheel_separation_m, wheel_radius_m=WHEEL_RADIUS_M,
                 acceleration_mps2=WHEEL_ACCELERATION_MPS2, update_rate_hz=DRIVE_UPDATE_RATE_HZ, limits=None):
        self.wheel_separation_m = wheel_separation_m
        self.wheel_radius_m = wheel_radius_m
        self.acceleration_mps2 = acceleration_mps2
        self.limits = limits
        self._schedule = PeriodicSchedule(update_rate_hz)
        self.reset(0.0)

    def reset(self, now_s):
        """Zero the command, the wheel speeds and the wheel angles, as Gazebo's plugin Reset() does."""
        self._command = (0.0, 0.0)
        self._target = [0.0, 0.0]
        self._rim = [0.0, 0.0]
        self._angles = [0.0, 0.0]
        self._last_update_s = now_s
        self._schedule.reset(now_s)

    def set_command(self, linear_mps, angular_radps):
        """Hold (linear_mps, angular_radps) as the command until the next one; raises InvalidCommandError."""
        reason = validate_command(linear_mps, angular_radps)
        if reason is not None:
            raise InvalidCommandError(reason)
        if self.limits is not None:
            max_linear, max_angular = self.limits
            linear_mps = max(-max_linear, min(max_linear, linear_mps))
            angular_radps = max(-max_angular, min(max_angular, angular_radps))
        self._command = (float(linear_mps), float(angular_radps))
        half_turn = angular_radps * self.wheel_separation_m / 2.0
        self._target = [linear_mps - half_turn, linear_mps + half_turn]

    @property
    def command(self):
        """The held command (linear m/s, angular rad/s)."""
        return self._command

    def update(self, now_s):
        """Move the rim speeds toward their targets if an update is due at `now_s` (sim seconds)."""
        if not self._schedule.due(now_s):
            return
        dt_s = now_s - self._last_update_s
        self._last_update_s = now_s
        near = any(abs(t - r) < WHEEL_SPEED_TOLERANCE_MPS for t, r in zip(self._target, self._rim))
        if self.acceleration_mps2 <= 0 or near:
            self._rim = list(self._target)
            return
        max_change = self.acceleration_mps2 * dt_s
        self._rim = [r + max(-max_change, min(max_change, t - r)) for t, r in zip(self._target, self._rim)]

    def advance_wheels(self, dt_s):
        """Turn the wheels by their current speed over `dt_s` seconds."""
        self._angles = [a + r / self.wheel_radius_m * dt_s for a, r in zip(self._angles, self._rim)]

    @property
    def velocity(self):
        """Body velocity (linear m/s along base_footprint x, angular rad/s) the wheels are driving now."""
        left, right = self._rim
        return (left + right) / 2.0, (right - left) / self.wheel_separation_m

    @property
    def wheel_angles(self):
        """Accumulated (left, right) wheel joint angles in rad, for /joint_states."""
        return tuple(self._angles)

    @property
    def wheel_speeds(self):
        """(left, right) wheel joint speeds in rad/s."""
        return tuple(r / self.wheel_radius_m for r in self._rim)
