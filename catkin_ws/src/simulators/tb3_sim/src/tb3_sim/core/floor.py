"""The floor layer of a world: a rectangle of base colour, an optional raster image and markings, as immutable data.

World frame, metres; angles in degrees where the field says `_deg` (anticlockwise from +x). Colours are (r, g, b)
0-255 as the file gives them, unlit (the camera applies the floor's lighting, see materials.FLOOR_LIGHT).
Markings are drawn in list order, later ones on top, over the image, which lies over the base colour. Outside the
floor rectangle a camera sees Gazebo's background grey (materials.SKY_RGB). A world without a floor layer keeps
Gazebo's infinite grey ground plane.

A stroke (`Stroke`) makes an outline: `width` metres wide centred on the path, optionally dashed (`dash` =
(on, off) metres along the path) and, on open paths (arc, polyline, curve), with a filled arrowhead `arrow_length`
metres long at its `arrow` end ("start" or "end"), pointing along the path. A rectangle, polygon or circle with
no stroke is filled; with a stroke only its outline is drawn.
"""

from dataclasses import dataclass
from typing import Optional, Tuple

import numpy as np

from tb3_sim.core.shapes import Point, Rgb

ARROW_ENDS = ("start", "end")
# An arrowhead is this many stroke widths long unless `arrow_length` says otherwise.
DEFAULT_ARROW_LENGTH_WIDTHS = 3.0


@dataclass(frozen=True)
class Stroke:
    """An outline `width` m wide; `dash` (on, off) m or None (solid); `arrow` "start"/"end"/None and its length."""

    width: float
    dash: Optional[Tuple[float, float]] = None
    arrow: Optional[str] = None
    arrow_length: float = 0.0


@dataclass(frozen=True)
class RectangleMarking:
    """A rectangle `size` (x, y) m centred on `center`, turned by `yaw_deg`."""

    center: Point
    size: Tuple[float, float]
    yaw_deg: float
    rgb: Rgb
    stroke: Optional[Stroke] = None


@dataclass(frozen=True)
class PolygonMarking:
    """A simple polygon (no self-crossing), either winding."""

    points: Tuple[Point, ...]
    rgb: Rgb
    stroke: Optional[Stroke] = None


@dataclass(frozen=True)
class CircleMarking:
    """A disc (or, with a stroke, a ring) of `radius` m."""

    center: Point
    radius: float
    rgb: Rgb
    stroke: Optional[Stroke] = None


@dataclass(frozen=True)
class ArcMarking:
    """A stroke along the circle of `radius` m from `start_deg` anticlockwise to `end_deg`."""

    center: Point
    radius: float
    start_deg: float
    end_deg: float
    rgb: Rgb
    stroke: Stroke


@dataclass(frozen=True)
class PolylineMarking:
    """A stroke through `points`; `closed` joins the last point back to the first."""

    points: Tuple[Point, ...]
    closed: bool
    rgb: Rgb
    stroke: Stroke


@dataclass(frozen=True)
class CurveMarking:
    """A chain of cubic Béziers as SVG's path "C" gives them: p0, c1, c2, p1, c1, c2, p2, ... (3n + 1 points)."""

    points: Tuple[Point, ...]
    rgb: Rgb
    stroke: Stroke


@dataclass(frozen=True)
class TextMarking:
    """`text` whose glyph box is centred on `position`, cap height `height` m, reading along `angle_deg`."""

    text: str
    position: Point
    height: float
    angle_deg: float
    bold: bool
    rgb: Rgb


@dataclass(frozen=True, eq=False)
class FloorImage:
    """A raster laid on the floor: `pixels` (H, W, 3) uint8 RGB, row 0 at +y, covering `size` m centred on `center`,
    turned by `yaw_deg`. `path` is the file it came from."""

    path: str
    pixels: np.ndarray
    center: Point
    size: Tuple[float, float]
    yaw_deg: float


@dataclass(frozen=True)
class Floor:
    """The visible floor rectangle (`size` m centred on `center`), its base colour, image and markings."""

    size: Tuple[float, float]
    center: Point
    rgb: Rgb
    image: Optional[FloorImage] = None
    markings: Tuple = ()

    def bounds(self):
        """(x_min, y_min, x_max, y_max) of the floor rectangle, metres."""
        (cx, cy), (sx, sy) = self.center, self.size
        return cx - sx / 2.0, cy - sy / 2.0, cx + sx / 2.0, cy + sy / 2.0
