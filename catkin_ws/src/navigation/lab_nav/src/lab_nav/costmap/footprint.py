"""The robot's footprint polygon: padding and the inscribed/circumscribed radii costmap_2d derives from it.

Coordinates are metres in base_footprint (x forward, y left). costmap_2d pads each vertex away from the
origin by footprint_padding on both axes; the inscribed radius is the distance from the origin to the nearest
edge, the circumscribed radius the distance to the farthest vertex. With turtlebot3's waffle footprint and the
default padding 0.01 that gives 0.087 m and 0.271 m, with the burger's 0.051 m and 0.163 m.
"""
from dataclasses import dataclass

import numpy as np

DEFAULT_PADDING_M = 0.01

WAFFLE_FOOTPRINT = ((-0.205, -0.155), (-0.205, 0.155), (0.077, 0.155), (0.077, -0.155))
BURGER_FOOTPRINT = ((-0.105, -0.105), (-0.105, 0.105), (0.041, 0.105), (0.041, -0.105))


class FootprintError(ValueError):
    """A footprint that is not a polygon of at least three (x, y) points."""


def _point_segment_distance(p, a, b):
    ab = b - a
    t = np.clip(np.dot(p - a, ab) / max(np.dot(ab, ab), 1e-12), 0.0, 1.0)
    return float(np.linalg.norm(p - (a + t * ab)))


@dataclass(frozen=True)
class Footprint:
    """A padded footprint polygon (vertices in order) in base_footprint."""

    points: tuple

    @classmethod
    def padded(cls, points, padding=DEFAULT_PADDING_M):
        pts = np.asarray(points, dtype=float)
        if pts.ndim != 2 or pts.shape[1] != 2 or len(pts) < 3 or not np.all(np.isfinite(pts)):
            raise FootprintError(f"a footprint needs at least three [x, y] points, got {points!r}")
        pts = pts + np.sign(pts) * padding
        return cls(tuple(map(tuple, pts.tolist())))

    @property
    def array(self):
        return np.asarray(self.points, dtype=float)

    @property
    def inscribed_radius(self):
        pts, origin = self.array, np.zeros(2)
        return min(_point_segment_distance(origin, pts[i], pts[(i + 1) % len(pts)]) for i in range(len(pts)))

    @property
    def circumscribed_radius(self):
        return float(np.max(np.linalg.norm(self.array, axis=1)))

    def outline(self, step):
        """Points along the polygon's edges, no farther than `step` m apart, (K, 2) in base_footprint."""
        pts = self.array
        samples = []
        for a, b in zip(pts, np.roll(pts, -1, axis=0)):
            n = max(1, int(np.ceil(np.linalg.norm(b - a) / step)))
            t = np.arange(n)[:, None] / n
            samples.append(a + t * (b - a))
        return np.vstack(samples)

    def placed(self, x, y, yaw, points=None):
        """`points` in base_footprint ((K, 2); the polygon's vertices by default) at pose (x, y, yaw), (K, 2)."""
        c, s = np.cos(yaw), np.sin(yaw)
        pts = self.array if points is None else points
        return np.column_stack((x + c * pts[:, 0] - s * pts[:, 1], y + s * pts[:, 0] + c * pts[:, 1]))
