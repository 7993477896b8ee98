"""A CameraSweep goal (tuos_msgs/CameraSweep) as a plan: the checked numbers, the angles at which to capture
and how long the sweep may take (plain Python, no rospy).

Choices where the course is silent or loose, kept from the COM2009 template where it has one:
- sweep_angle is in degrees, in (0, MAX_SWEEP_ANGLE_DEG] = (0, 180] as the course's server accepts. The robot
  always turns anticlockwise (to its left, positive yaw), so a negative angle is refused rather than read as
  "turn right"; NaN and infinities are refused too.
- image_count is 1..50 (the course's maximum).
- Capture angles are spread as the course's server does: image k (1..n) is taken once the robot has turned
  k * sweep_angle / n degrees, so the first image comes after one step and the last at the end of the sweep;
  none is taken at the start.
- A sweep may take at most SWEEP_TIME_FACTOR times its ideal duration plus SWEEP_TIME_MARGIN_S (sim seconds);
  a robot that turns slower than that (blocked, or commands lost) ends the goal aborted instead of hanging.
"""
import math
from typing import NamedTuple

MAX_SWEEP_ANGLE_DEG = 180.0
MIN_IMAGE_COUNT = 1
MAX_IMAGE_COUNT = 50
DEFAULT_ANGULAR_SPEED_RADPS = 0.4   # 90 degrees in about 4 s (the course's template turns at 0.2 rad/s)
SWEEP_TIME_FACTOR = 2.0
SWEEP_TIME_MARGIN_S = 5.0


class SweepError(Exception):
    """Root of this package's errors: the goal cannot be (or could not be) carried out; the text says why."""


class InvalidGoal(SweepError, ValueError):
    """The goal is refused before the robot moves; the text names each bad field and what is allowed."""


class SweepFailed(SweepError, RuntimeError):
    """A valid sweep could not be completed (the robot did not turn, the camera stopped, a file could not be
    written)."""


class SweepPlan(NamedTuple):
    """A checked goal: sweep `sweep_angle_deg` degrees anticlockwise at `angular_speed_radps`, capturing
    `image_count` images."""

    sweep_angle_deg: float
    image_count: int
    angular_speed_radps: float

    @property
    def step_deg(self):
        """Degrees turned between two captures."""
        return self.sweep_angle_deg / self.image_count

    @property
    def capture_angles_deg(self):
        """The angle turned (degrees from the start) at which each image is captured, first to last."""
        return tuple(self.sweep_angle_deg * k / self.image_count for k in range(1, self.image_count + 1))

    @property
    def ideal_duration_s(self):
        """Seconds the whole sweep takes at the commanded speed, ignoring acceleration."""
        return math.radians(self.sweep_angle_deg) / self.angular_speed_radps

    @property
    def time_limit_s(self):
        """Seconds (rospy time) after which an unfinished sweep is given up."""
        return SWEEP_TIME_FACTOR * self.ideal_duration_s + SWEEP_TIME_MARGIN_S


def plan_sweep(sweep_angle, image_count, angular_speed_radps=DEFAULT_ANGULAR_SPEED_RADPS):
    """The SweepPlan for a goal, or InvalidGoal listing every field that is out of range (module docstring)."""
    problems = []
    if not math.isfinite(sweep_angle):
        problems.append("sweep_angle {} is not a finite number of degrees".format(sweep_angle))
    elif not 0.0 < sweep_angle <= MAX_SWEEP_ANGLE_DEG:
        problems.append("sweep_angle {:g} degrees is not in (0, {:g}]: the robot sweeps anticlockwise, by at most "
                        "{:g} degrees".format(sweep_angle, MAX_SWEEP_ANGLE_DEG, MAX_SWEEP_ANGLE_DEG))
    if not MIN_IMAGE_COUNT <= image_count <= MAX_IMAGE_COUNT:
        problems.append("image_count {} is not in {}..{}: {}".format(
            image_count, MIN_IMAGE_COUNT, MAX_IMAGE_COUNT,
            "there must be at least one image" if image_count < MIN_IMAGE_COUNT
            else "that is too many images, the maximum is {}".format(MAX_IMAGE_COUNT)))
    if problems:
        raise InvalidGoal("; ".join(problems))
    return SweepPlan(float(sweep_angle), int(image_count), float(angular_speed_radps))
