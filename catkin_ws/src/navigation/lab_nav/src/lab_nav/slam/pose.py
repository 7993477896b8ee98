"""2D poses (x m, y m, theta rad) as plain tuples: composition and inverse, as tf composes transforms."""

import math


def compose(a, b):
    """a (+) b: the pose b, given in a's frame, expressed in the frame a is given in."""
    ax, ay, at = a
    bx, by, bt = b
    c, s = math.cos(at), math.sin(at)
    return (ax + c * bx - s * by, ay + s * bx + c * by, wrap_angle(at + bt))


def inverse(a):
    """The pose p with compose(a, p) == (0, 0, 0)."""
    ax, ay, at = a
    c, s = math.cos(at), math.sin(at)
    return (-c * ax - s * ay, s * ax - c * ay, wrap_angle(-at))


def between(a, b):
    """The motion from a to b in a's frame: compose(inverse(a), b)."""
    return compose(inverse(a), b)


def wrap_angle(angle):
    """angle in (-pi, pi]."""
    return math.atan2(math.sin(angle), math.cos(angle))
