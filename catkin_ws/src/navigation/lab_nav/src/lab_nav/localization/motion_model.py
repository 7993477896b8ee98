"""amcl's diff-drive odometry motion model: the odometry step as rotate, translate, rotate, with noise.

An odometry change from pose a to pose b (x, y, yaw in the odom frame) splits into rot1 (turn toward the
motion), trans (distance) and rot2 (remaining turn); a move shorter than 1 cm has rot1 = 0. Each particle applies
the three with Gaussian noise of variance alpha1*rot^2 + alpha2*trans^2 (rotations) and alpha3*trans^2 +
alpha4*(rot1^2 + rot2^2) (translation), where a rotation counts the smaller of its angle and its angle from
pi, so driving backwards is not mistaken for a half turn (amcl's treatment).
"""
from dataclasses import dataclass

import numpy as np

from ..angles import normalize

MIN_TRANSLATION_M = 0.01


@dataclass(frozen=True)
class OdometryNoise:
    """odom_alpha1..4 (turtlebot3's amcl.launch: 0.1 each)."""

    alpha1: float = 0.1
    alpha2: float = 0.1
    alpha3: float = 0.1
    alpha4: float = 0.1


def decompose(a, b):
    """(rot1, trans, rot2) of the odometry change from pose a to pose b."""
    dx, dy = b[0] - a[0], b[1] - a[1]
    trans = float(np.hypot(dx, dy))
    rot1 = 0.0 if trans < MIN_TRANSLATION_M else float(normalize(np.arctan2(dy, dx) - a[2]))
    rot2 = float(normalize(b[2] - a[2] - rot1))
    return rot1, trans, rot2


def _rotation_noise(rot):
    return min(abs(float(normalize(rot))), abs(float(normalize(rot - np.pi))))


def sample(poses, a, b, noise, rng):
    """The particles (N, 3) moved by the odometry change a -> b with sampled noise (a new array)."""
    rot1, trans, rot2 = decompose(a, b)
    n1, n2 = _rotation_noise(rot1), _rotation_noise(rot2)
    count = len(poses)
    r1 = rot1 - rng.normal(0.0, np.sqrt(noise.alpha1 * n1 ** 2 + noise.alpha2 * trans ** 2), count)
    tr = trans - rng.normal(0.0, np.sqrt(noise.alpha3 * trans ** 2 + noise.alpha4 * (n1 ** 2 + n2 ** 2)), count)
    r2 = rot2 - rng.normal(0.0, np.sqrt(noise.alpha1 * n2 ** 2 + noise.alpha2 * trans ** 2), count)
    out = np.empty_like(poses)
    heading = poses[:, 2] + r1
    out[:, 0] = poses[:, 0] + tr * np.cos(heading)
    out[:, 1] = poses[:, 1] + tr * np.sin(heading)
    out[:, 2] = normalize(heading + r2)
    return out
