"""amcl's diff-drive odometry motion model: the odometry step as rotate, translate, rotate, with noise.

An odometry change from pose a to pose b (x, y, yaw in the odom frame) splits into rot1 (turn toward the
motion), trans (distance) and rot2 (remaining turn); a move shorter than 1 cm has rot1 = 0. Each particle applies
the three with Gaussian noise whose spread is alpha1*rot^2 + alpha2*trans^2 (rotations) and alpha3*trans^2 +
alpha4*(rot1^2 + rot2^2) (translation), where a rotation counts the smaller of its angle and its angle from
pi, so driving backwards is not mistaken for a half turn (amcl's treatment).

odom_model_type picks what that spread is (SPREADS): amcl's "diff" model, which turtlebot3's amcl.launch uses,
passes the expression itself as the standard deviation (a quirk kept on purpose: with odom_alpha 0.1 a 0.2 m step
moves a particle by 0.004 m of noise, so a filter on good odometry barely diffuses along a corridor the laser
cannot pin down); "diff-corrected" takes its square root, the textbook variance (0.063 m for the same step: in
turtlebot3_house's open south room that diffusion let the estimate slide 1.5 m along the wall in 6 m of driving).
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


SPREADS = {
    "diff": lambda expression: expression,
    "diff-corrected": np.sqrt,
}
"""odom_model_type -> the standard deviation of a noise term from its alpha expression."""


def _rotation_noise(rot):
    return min(abs(float(normalize(rot))), abs(float(normalize(rot - np.pi))))


def sample(poses, a, b, noise, rng, model="diff"):
    """The particles (N, 3) moved by the odometry change a -> b with sampled noise (a new array); `model` is an
    odom_model_type of SPREADS."""
    spread = SPREADS[model]
    rot1, trans, rot2 = decompose(a, b)
    n1, n2 = _rotation_noise(rot1), _rotation_noise(rot2)
    count = len(poses)
    r1 = rot1 - rng.normal(0.0, spread(noise.alpha1 * n1 ** 2 + noise.alpha2 * trans ** 2), count)
    tr = trans - rng.normal(0.0, spread(noise.alpha3 * trans ** 2 + noise.alpha4 * (n1 ** 2 + n2 ** 2)), count)
    r2 = rot2 - rng.normal(0.0, spread(noise.alpha1 * n2 ** 2 + noise.alpha2 * trans ** 2), count)
    out = np.empty_like(poses)
    heading = poses[:, 2] + r1
    out[:, 0] = poses[:, 0] + tr * np.cos(heading)
    out[:, 1] = poses[:, 1] + tr * np.sin(heading)
    out[:, 2] = normalize(heading + r2)
    return out
