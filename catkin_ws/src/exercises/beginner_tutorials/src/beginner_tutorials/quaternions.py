"""Roll/pitch/yaw <-> quaternion, through tf.transformations as the tutorial does.

Angles are radians about the fixed x, y, z axes (REP 103, tf's default 'sxyz'); quaternions are (x, y, z, w)
as in geometry_msgs/Quaternion. q and -q are the same rotation, and a pitch beyond +-pi/2 comes back as an
equivalent triple with pitch inside it, so a round trip is checked by comparing rotations, not numbers.

Debian's python3-tf loads rospy when `tf` is imported (its __init__ pulls in the listener); nothing here
uses it, and no master is needed.
"""
import math
from typing import NamedTuple

from tf.transformations import euler_from_quaternion, quaternion_from_euler

from .errors import UsageError

ROTATION_TOLERANCE = 1e-9


class EulerAngles(NamedTuple):
    roll: float
    pitch: float
    yaw: float


class Quaternion(NamedTuple):
    x: float
    y: float
    z: float
    w: float


DEFAULT_ANGLES = EulerAngles(0.0, 0.0, math.pi / 2)


def to_quaternion(angles):
    return Quaternion(*(float(value) for value in quaternion_from_euler(*angles)))


def to_euler(quaternion):
    return EulerAngles(*(float(value) for value in euler_from_quaternion(quaternion)))


def same_rotation(first, second, tolerance=ROTATION_TOLERANCE):
    """True when two unit quaternions describe one rotation (equal up to sign)."""
    dot = sum(a * b for a, b in zip(first, second))
    return abs(abs(dot) - 1.0) <= tolerance


def usage(program):
    return ("usage: {} [ROLL PITCH YAW]\n"
            "  converts the angles (radians, default 0 0 {:.4f}) to a quaternion and back").format(
                program, DEFAULT_ANGLES.yaw)


def parse_angles(args):
    """No arguments (the default angles) or three finite numbers in radians."""
    if not args:
        return DEFAULT_ANGLES
    if len(args) != 3:
        raise UsageError("expected 0 or 3 arguments (ROLL PITCH YAW); got {}".format(len(args)))
    values = []
    for text in args:
        try:
            value = float(text)
        except ValueError:
            raise UsageError("{!r} is not a number".format(text)) from None
        if not math.isfinite(value):
            raise UsageError("{} is not a finite angle".format(text))
        values.append(value)
    return EulerAngles(*values)
