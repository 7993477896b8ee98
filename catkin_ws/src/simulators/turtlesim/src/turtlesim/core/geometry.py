"""Small value types and numeric rules shared by the core.

Frames: see constants. Values published by the original are float32; `as_float32` rounds a
Python float the same way, returning a Python float so ROS messages take it unchanged.
"""
import math
from typing import NamedTuple

import numpy

from turtlesim.core.constants import PI

QT_FUZZY_NULL = 1e-12
"""Absolute tolerance of qFuzzyIsNull(double) in Qt 5."""

QT_FUZZY_SCALE = 1e12
"""Relative scale of qFuzzyCompare(double, double) in Qt 5."""


class Pose(NamedTuple):
    """A turtle's pose as turtlesim/Pose: world metres, radians, m/s, rad/s; float32 values."""

    x: float
    y: float
    theta: float
    linear_velocity: float
    angular_velocity: float


def as_float32(value):
    """Round `value` to the nearest float32 (overflow gives +-inf) and return a Python float."""
    with numpy.errstate(over='ignore'):
        return float(numpy.float32(value))


def all_finite(*values):
    """True when every value is a finite number."""
    return all(math.isfinite(value) for value in values)


def wrap_heading(theta):
    """Wrap radians into [-PI, PI) exactly as the original: theta - 2PI*floor((theta+PI)/2PI).

    PI is the original's 3.14159265, so the range is slightly narrower than [-pi, pi).
    """
    return theta - 2 * PI * math.floor((theta + PI) / (2 * PI))


def qt_fuzzy_equal(a, b):
    """One coordinate of Qt 5's QPointF ==: relative 1e-12 compare, absolute when either is 0."""
    if a == 0.0 or b == 0.0:
        return abs(a - b) <= QT_FUZZY_NULL
    return abs(a - b) * QT_FUZZY_SCALE <= min(abs(a), abs(b))
