"""move_base's checks of a goal's orientation, with the original's console and abort texts.

A goal's quaternion must be finite, of non-negligible length and a pure rotation about z (its z axis within
1e-3 of vertical after normalising); otherwise move_base aborts the goal at once.
"""
import numpy as np

INVALID_QUATERNION_ABORT = "Aborting on goal because it was sent with an invalid quaternion"
NAN_QUATERNION = "Quaternion has nans or infs... discarding as navigation goal"
ZERO_QUATERNION = "Quaternion has length close to zero... discarding as navigation goal"
TILTED_QUATERNION = ("Quaternion is invalid... for navigation the z-axis of the quaternion must be close to "
                     "vertical.")
MIN_LENGTH_SQUARED = 1e-6
VERTICAL_TOLERANCE = 1e-3


def quaternion_problem(x, y, z, w):
    """None for a usable goal orientation, else the ERROR line move_base logs for it."""
    q = np.array([x, y, z, w], dtype=float)
    if not np.all(np.isfinite(q)):
        return NAN_QUATERNION
    if np.dot(q, q) < MIN_LENGTH_SQUARED:
        return ZERO_QUATERNION
    x, y, z, w = q / np.linalg.norm(q)
    z_axis_z = 1.0 - 2.0 * (x * x + y * y)   # z component of the rotated z axis
    if abs(z_axis_z - 1.0) > VERTICAL_TOLERANCE:
        return TILTED_QUATERNION
    return None
