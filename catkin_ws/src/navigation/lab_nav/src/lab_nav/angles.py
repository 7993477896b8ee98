"""Angle helpers shared by the planners and the particle filter (radians)."""
import numpy as np


def normalize(angle):
    """The angle wrapped into [-pi, pi) (works on arrays)."""
    return (np.asarray(angle) + np.pi) % (2 * np.pi) - np.pi


def yaw_of_quaternion(x, y, z, w):
    """Yaw (rad) of a quaternion (any length > 0), the rotation about z."""
    return float(np.arctan2(2.0 * (w * z + x * y), 1.0 - 2.0 * (y * y + z * z)))
