"""What the LiDAR can see, as flat numpy arrays in the world frame (metres).

Lines and circles. A line is either a two-sided wall segment or an edge of a solid convex polygon wound CCW
(`solid` is True): a ray from outside can only first hit an edge that faces it, so the ray caster drops back
faces. Circles are pillars and cylinder models. Solid shapes are seen from outside only: a beam that starts inside one
(possible only within the 0.12 m blind zone) sees through it.
"""

from dataclasses import dataclass, fields

import numpy as np

from tb3_sim.core.materials import DEFAULT_MODEL_RGB, DEFAULT_WALL_RGB, ROBOT_RGB
from tb3_sim.core.shapes import DEFAULT_STATIC_HEIGHT_M, Box, Circle, Cylinder, Polygon, Segment
from tb3_sim.core.turtlebot3 import LDS_RADIUS_M, LDS_TOP_ABOVE_SCAN_M, LDS_X_OFFSET_M


@dataclass(frozen=True)
class Obstacles:
    """`lines` (M, 4) rows x1, y1, x2, y2 with `solid` (M,) flags; `circles` (K, 3) rows cx, cy, r.

    For the camera each line and circle also has a top (`line_tops` (M,), `circle_tops` (K,): metres above
    the floor, every object standing on it) and a colour (`line_rgb` (M, 3), `circle_rgb` (K, 3): uint8).
    """

    lines: np.ndarray
    solid: np.ndarray
    circles: np.ndarray
    line_tops: np.ndarray
    line_rgb: np.ndarray
    circle_tops: np.ndarray
    circle_rgb: np.ndarray

    @classmethod
    def empty(cls):
        return cls.of()

    @classmethod
    def of(cls, segments=(), edges=(), circles=(), top=DEFAULT_STATIC_HEIGHT_M, rgb=DEFAULT_WALL_RGB):
        """Obstacles from lists of (x1, y1, x2, y2) segments and CCW edges, and (cx, cy, r) circles, all with
        the same `top` (m) and `rgb` colour."""
        segments = np.asarray(segments, dtype=float).reshape(-1, 4)
        edges = np.asarray(edges, dtype=float).reshape(-1, 4)
        circles = np.asarray(circles, dtype=float).reshape(-1, 3)
        lines = len(segments) + len(edges)
        return cls(np.concatenate((segments, edges)),
                   np.concatenate((np.zeros(len(segments), dtype=bool), np.ones(len(edges), dtype=bool))),
                   circles, np.full(lines, float(top)), np.tile(np.asarray(rgb, dtype=np.uint8), (lines, 1)),
                   np.full(len(circles), float(top)), np.tile(np.asarray(rgb, dtype=np.uint8), (len(circles), 1)))

    def __add__(self, other):
        return Obstacles(*(np.concatenate((mine, theirs)) for mine, theirs in zip(astuple_shallow(self),
                                                                                    astuple_shallow(other))))


def astuple_shallow(obstacles):
    """The arrays of `obstacles` in field order (dataclasses.astuple would deep-copy them)."""
    return tuple(getattr(obstacles, f.name) for f in fields(obstacles))


def _ccw_edges(points):
    """Edges of a convex polygon as (n, 4) rows, wound CCW whatever the input winding."""
    closed = np.asarray(points, dtype=float)
    x, y = closed[:, 0], closed[:, 1]
    if np.dot(x, np.roll(y, -1)) - np.dot(np.roll(x, -1), y) < 0:
        closed = closed[::-1]
    return np.hstack((closed, np.roll(closed, -1, axis=0)))


def static_obstacles(shapes):
    """Obstacles for static world shapes (`Segment`, `Polygon`, `Circle`), each with its height and colour."""
    parts = [Obstacles.empty()]
    for shape in shapes:
        look = {"top": shape.height, "rgb": shape.rgb or DEFAULT_WALL_RGB}
        if isinstance(shape, Segment):
            parts.append(Obstacles.of(segments=[(*shape.start, *shape.end)], **look))
        elif isinstance(shape, Polygon):
            parts.append(Obstacles.of(edges=_ccw_edges(shape.points), **look))
        elif isinstance(shape, Circle):
            parts.append(Obstacles.of(circles=[(*shape.center, shape.radius)], **look))
        else:
            raise TypeError(f"not a static shape: {shape!r}")
    return sum(parts[1:], parts[0])


def model_obstacles(shape, pose, rgb=None):
    """Obstacles for a model shape (`Box` or `Cylinder`) whose origin is at `pose` (world), coloured `rgb`
    (Gazebo's default model grey if None)."""
    look = {"top": shape.height, "rgb": rgb or DEFAULT_MODEL_RGB}
    if isinstance(shape, Box):
        return Obstacles.of(edges=_ccw_edges([pose.compose(x, y) for x, y in shape.corners()]), **look)
    if isinstance(shape, Cylinder):
        return Obstacles.of(circles=[(pose.x, pose.y, shape.radius)], **look)
    raise TypeError(f"not a model shape: {shape!r}")


def robot_obstacles(model, pose, reaching_m=0.0):
    """Obstacles for a TurtleBot3 of `model` (a turtlebot3.TurtleBot3Model) at `pose`: its base box and its LiDAR
    housing, each only if its top reaches `reaching_m` (a Waffle's LiDAR plane passes above another Waffle's base
    and meets its LiDAR housing)."""
    parts = [Obstacles.empty()]
    if model.body_top_m >= reaching_m:
        base = model.footprint()[0]
        parts.append(Obstacles.of(edges=_ccw_edges([pose.compose(x, y) for x, y in base]), top=model.body_top_m,
                                  rgb=ROBOT_RGB))
    lds_top = model.scan_height_m + LDS_TOP_ABOVE_SCAN_M
    if lds_top >= reaching_m:
        x, y = pose.compose(model.scan_x_m + LDS_X_OFFSET_M, 0.0)
        parts.append(Obstacles.of(circles=[(x, y, LDS_RADIUS_M)], top=lds_top, rgb=ROBOT_RGB))
    return sum(parts[1:], parts[0])
