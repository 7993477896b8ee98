"""What the LiDAR can see, as flat numpy arrays: segments and circles in the world frame.

Polygons and boxes become their edges (a ray from outside hits the near edge first; from inside, the wall
it faces). Cylinders and static circles stay circles.
"""

from dataclasses import dataclass

import numpy as np

from tb3_sim.shapes import Box, Circle, Cylinder, Polygon, Segment


@dataclass(frozen=True)
class Obstacles:
    """`segments` is an (M, 4) array of x1, y1, x2, y2; `circles` a (K, 3) array of cx, cy, r. Metres, world."""

    segments: np.ndarray
    circles: np.ndarray

    @classmethod
    def empty(cls):
        return cls(np.zeros((0, 4)), np.zeros((0, 3)))

    def __add__(self, other):
        return Obstacles(np.concatenate((self.segments, other.segments)),
                         np.concatenate((self.circles, other.circles)))


def _polygon_edges(points):
    closed = np.asarray(points, dtype=float)
    return np.hstack((closed, np.roll(closed, -1, axis=0)))


def static_obstacles(shapes):
    """Obstacles for static world shapes (`Segment`, `Polygon`, `Circle`), in the order given."""
    segments, circles = [np.zeros((0, 4))], [np.zeros((0, 3))]
    for shape in shapes:
        if isinstance(shape, Segment):
            segments.append(np.array([[*shape.start, *shape.end]], dtype=float))
        elif isinstance(shape, Polygon):
            segments.append(_polygon_edges(shape.points))
        elif isinstance(shape, Circle):
            circles.append(np.array([[*shape.center, shape.radius]], dtype=float))
        else:
            raise TypeError(f"not a static shape: {shape!r}")
    return Obstacles(np.concatenate(segments), np.concatenate(circles))


def model_obstacles(shape, pose):
    """Obstacles for a model shape (`Box` or `Cylinder`) whose origin is at `pose` (world)."""
    if isinstance(shape, Box):
        corners = [pose.compose(x, y) for x, y in shape.corners()]
        return Obstacles(_polygon_edges(corners), np.zeros((0, 3)))
    if isinstance(shape, Cylinder):
        return Obstacles(np.zeros((0, 4)), np.array([[pose.x, pose.y, shape.radius]]))
    raise TypeError(f"not a model shape: {shape!r}")
