"""turtle_actionlib's shape_server polygon controller (ShapeAction::goalCB/controlCB), no ROS.

Drives turtle1 around a regular polygon: drive an edge, turn left by the exterior angle,
repeat. One command per received Pose; the controller relies on turtlesim's 0.016 s ticks.
All arithmetic is double, as in the C++; the result fields are float32.
"""
import math
from typing import NamedTuple, Optional, Tuple

import numpy

from turtlesim.core.geometry import as_float32

LINEAR_SCALE = 6.0
"""Gain from remaining edge length (m) to linear.x (m/s)."""

ANGULAR_SCALE = 6.0
"""Gain from remaining turn (rad) to angular.z (rad/s)."""

ERROR_TOLERANCE = 0.00001
"""Edge length (m) and turn (rad) errors below this count as done."""

SUCCEEDED_LOG = '%s: Succeeded'
"""INFO text when the goal succeeds, formatted with the action name (e.g. /turtle_shape)."""

PREEMPTED_LOG = '%s: Preempted'
"""INFO text when the goal is preempted, formatted with the action name."""


class ShapeResult(NamedTuple):
    """turtle_actionlib/ShapeResult: interior angle (rad) and apothem (m), float32 values."""

    interior_angle: float
    apothem: float


class ShapeStep(NamedTuple):
    """Outcome of one Pose: `command` (linear.x m/s, angular.z rad/s) to publish, or None;
    `succeeded` True once every edge is done (set the goal succeeded with the result)."""

    command: Optional[Tuple[float, float]]
    succeeded: bool


def normalize_angle_positive(angle):
    """angles::normalize_angle_positive: the angle in radians mapped into [0, 2*pi)."""
    result = math.fmod(angle, 2.0 * math.pi)
    return result + 2.0 * math.pi if result < 0 else result


class ShapeController:
    """Controller for one accepted goal; create a new one for each goal (goalCB)."""

    def __init__(self, edges, radius):
        """Compute the polygon from the goal: `edges` (int32) and `radius` (float32, m).

        interior = (n-2)*pi/n, apothem = r*cos(pi/n), side = 2*apothem*tan(pi/n). Degenerate
        goals (edges <= 0) follow IEEE arithmetic as the C++ does and succeed at once.
        """
        self._edges = int(edges)
        with numpy.errstate(divide='ignore', invalid='ignore'):
            n = numpy.float64(self._edges)
            half_angle = numpy.float64(math.pi) / n
            interior = (n - 2) * numpy.float64(math.pi) / n
            apothem = numpy.float64(as_float32(radius)) * numpy.cos(half_angle)
            self._side = float(apothem * 2 * numpy.tan(half_angle))
        self._interior = float(interior)
        self.result = ShapeResult(as_float32(interior), as_float32(apothem))
        self._edge_progress = 0
        self._start_edge = True
        self._start = (0.0, 0.0, 0.0)

    @property
    def side_length(self):
        """Length of one polygon edge in metres (2*r*sin(pi/n))."""
        return self._side

    def on_pose(self, pose):
        """Handle one turtle1 Pose (anything with x, y, theta); return the ShapeStep."""
        if self._edge_progress >= self._edges:
            return ShapeStep(None, True)
        if self._start_edge:
            self._start = (pose.x, pose.y, pose.theta)
            self._start_edge = False
        start_x, start_y, start_theta = self._start
        distance_error = self._side - abs(math.sqrt((start_x - pose.x) * (start_x - pose.x)
                                                    + (start_y - pose.y) * (start_y - pose.y)))
        theta_error = normalize_angle_positive(
            math.pi - self._interior - (pose.theta - start_theta))
        if distance_error > ERROR_TOLERANCE:
            command = (LINEAR_SCALE * distance_error, 0.0)
        elif distance_error < ERROR_TOLERANCE and abs(theta_error) > ERROR_TOLERANCE:
            command = (0.0, ANGULAR_SCALE * theta_error)
        elif distance_error < ERROR_TOLERANCE and abs(theta_error) < ERROR_TOLERANCE:
            command = (0.0, 0.0)
            self._start_edge = True
            self._edge_progress += 1
        else:
            command = (LINEAR_SCALE * distance_error, ANGULAR_SCALE * theta_error)
        return ShapeStep(command, False)
