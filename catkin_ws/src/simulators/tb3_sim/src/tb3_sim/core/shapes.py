"""Shapes of static world geometry and of models, as immutable data.

All coordinates are metres. Static shapes are given in the world frame; model shapes (`Box`, `Cylinder`)
are centred on their model's origin and placed by the model's pose. `height` is the top of the object above
the floor: the LiDAR scans only the plane z = 0.132 m, so an object lower than that collides but is not seen by
it (see `visible_at`). `rgb` is what the camera sees: an (r, g, b) tuple of 0-255 ints, or None for the default
(materials.DEFAULT_WALL_RGB); a model's colour is on its ModelSpec.
"""

from dataclasses import dataclass
from typing import Optional, Tuple

Point = Tuple[float, float]
Rgb = Tuple[int, int, int]

# Outer wall of turtlebot3_world is about 1 m tall; used when a world file gives no height.
DEFAULT_STATIC_HEIGHT_M = 1.0


@dataclass(frozen=True)
class Segment:
    """A zero-thickness wall from `start` to `end` (world frame); collides and is seen from both sides."""

    start: Point
    end: Point
    height: float = DEFAULT_STATIC_HEIGHT_M
    rgb: Optional[Rgb] = None


@dataclass(frozen=True)
class Polygon:
    """A solid convex polygon (3 to 8 vertices, either winding) in the world frame."""

    points: Tuple[Point, ...]
    height: float = DEFAULT_STATIC_HEIGHT_M
    rgb: Optional[Rgb] = None


@dataclass(frozen=True)
class Circle:
    """A solid disc (an upright cylinder seen from above) in the world frame."""

    center: Point
    radius: float
    height: float = DEFAULT_STATIC_HEIGHT_M
    rgb: Optional[Rgb] = None


@dataclass(frozen=True)
class Box:
    """A model's box: `size_x` by `size_y` metres centred on the model origin, `height` metres tall."""

    size_x: float
    size_y: float
    height: float

    def corners(self):
        """CCW corners (x, y) in the model frame."""
        hx, hy = self.size_x / 2.0, self.size_y / 2.0
        return (-hx, -hy), (hx, -hy), (hx, hy), (-hx, hy)


@dataclass(frozen=True)
class Cylinder:
    """A model's upright cylinder of `radius` metres centred on the model origin, `height` metres tall.

    A sphere is represented as `Cylinder.sphere(r)`: a disc of radius r whose top is at 2r, the sphere's
    footprint on the floor and its top when resting on the ground.
    """

    radius: float
    height: float

    @classmethod
    def sphere(cls, radius):
        """The planar stand-in for a sphere of `radius` metres resting on the floor."""
        return cls(radius=radius, height=2.0 * radius)


def visible_at(shape, plane_height_m):
    """True if `shape` reaches up to the horizontal plane at `plane_height_m` (metres above the floor)."""
    return shape.height >= plane_height_m
