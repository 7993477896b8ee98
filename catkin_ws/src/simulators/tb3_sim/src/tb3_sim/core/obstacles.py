"""What the LiDAR can see, as flat numpy arrays in the world frame (metres).

Lines and circles. A line is either a two-sided wall segment or an edge of a solid convex polygon wound CCW
(`solid` is True): a ray from outside can only first hit an edge that faces it, so the ray caster drops back
faces. Circles are pillars and cylinder models. Solid shapes are seen from outside only: a beam that starts inside one
(possible only within the 0.12 m blind zone) sees through it.
"""

from dataclasses import dataclass

import numpy as np

from tb3_sim.core.shapes import Box, Circle, Cylinder, Polygon, Segment


@dataclass(frozen=True)
class Obstacles:
    """`lines` (M, 4) rows x1, y1, x2, y2 with `solid` (M,) flags; `circles` (K, 3) rows cx, cy, r."""

    lines: np.ndarray
    solid: np.ndarray
    circles: np.ndarray

    @classmethod
    def empty(cls):
        return cls(np.zeros((0, 4)), np.zeros(0, dtype=bool), np.zeros((0, 3)))

    @classmethod
    def of(cls, segments=(), edges=(), circles=()):
        """Obstacles from lists of (x1, y1, x2, y2) segments and CCW edges, and (cx, cy, r) circles."""
        segments = np.asarray(segments, dtype=float).reshape(-1, 4)
        edges = np.asarray(edges, dtype=float).reshape(-1, 4)
        return cls(np.concatenate((segments, edges)),
                   np.concatenate((np.zeros(len(segments), dtype=bool), np.ones(len(edges), dtype=bool))),
                   np.asarray(circles, dtype=float).reshape(-1, 3))

    def __add__(self, other):
        return Obstacles(np.concatenate((self.lines, other.lines)), np.concatenate((self.solid, other.solid)),
                         np.concatenate((self.circles, other.circles)))


def _ccw_edges(points):
    """Edges of a convex polygon as (n, 4) rows, wound CCW whatever the input winding."""
    closed = np.asarray(points, dtype=float)
    x, y = closed[:, 0], closed[:, 1]
    if np.dot(x, np.roll(y, -1)) - np.dot(np.roll(x, -1), y) < 0:
        closed = closed[::-1]
    return np.hstack((closed, np.roll(closed, -1, axis=0)))


def static_obstacles(shapes):
    """Obstacles for static world shapes (`Segment`, `Polygon`, `Circle`)."""
    segments, edges, circles = [], [np.zeros((0, 4))], []
    for shape in shapes:
        if isinstance(shape, Segment):
            segments.append((*shape.start, *shape.end))
        elif isinstance(shape, Polygon):
            edges.append(_ccw_edges(shape.points))
        elif isinstance(shape, Circle):
            circles.append((*shape.center, shape.radius))
        else:
            raise TypeError(f"not a static shape: {shape!r}")
    return Obstacles.of(segments, np.concatenate(edges), circles)


def model_obstacles(shape, pose):
    """Obstacles for a model shape (`Box` or `Cylinder`) whose origin is at `pose` (world)."""
    if isinstance(shape, Box):
        return Obstacles.of(edges=_ccw_edges([pose.compose(x, y) for x, y in shape.corners()]))
    if isinstance(shape, Cylinder):
        return Obstacles.of(circles=[(pose.x, pose.y, shape.radius)])
    raise TypeError(f"not a model shape: {shape!r}")
