"""The drawing primitives every top-down view draws and the camera's floor texture is rasterised from: a small
closed set, world frame, metres, colours (r, g, b) 0-255. A scene is a sequence of them, painted in order.

- FilledPolygon: rings filled with the even-odd rule (one ring for a simple polygon; a glyph's holes are rings too);
- Polyline: a stroke `width` m wide centred on the points, butt ends and round joins (SVG's stroke-linejoin round),
  `closed` joining the last point to the first;
- Disc: a filled circle;
- Text: a label whose glyph box is centred on `position`, cap height `height` m, reading along `angle_deg`; a
  renderer without fonts fills `text_outline.text_rings(text)`, which gives the same glyphs everywhere;
- Image: RGB pixels (row 0 at +y) covering `size` m centred on `center`, turned by `yaw_deg`.

`to_data(primitive)` is the JSON-ready form a browser receives (kind name plus fields; images as PNG data URLs).
A colour may be None in data meant for several views: "the view's own colour for walls" (a static shape that the
world file gave no colour).
"""

import base64
from dataclasses import dataclass
from typing import Tuple

import numpy as np

from tb3_sim.core.shapes import Point, Rgb


@dataclass(frozen=True)
class FilledPolygon:
    rings: Tuple[Tuple[Point, ...], ...]
    rgb: Rgb


@dataclass(frozen=True)
class Polyline:
    points: Tuple[Point, ...]
    width: float
    rgb: Rgb
    closed: bool = False


@dataclass(frozen=True)
class Disc:
    center: Point
    radius: float
    rgb: Rgb


@dataclass(frozen=True)
class Text:
    text: str
    position: Point
    height: float
    angle_deg: float
    bold: bool
    rgb: Rgb


@dataclass(frozen=True, eq=False)
class Image:
    pixels: np.ndarray
    center: Point
    size: Tuple[float, float]
    yaw_deg: float


def _image_data(image):
    import cv2  # about 0.4 s: paid only when an image is sent

    png = cv2.imencode(".png", np.ascontiguousarray(image.pixels[:, :, ::-1]))[1].tobytes()
    return {"src": "data:image/png;base64," + base64.b64encode(png).decode("ascii"), "center": _point(image.center),
            "size": list(image.size), "yaw_deg": image.yaw_deg}


def _fields(primitive):
    return {name: getattr(primitive, name) for name in primitive.__dataclass_fields__}


# Coordinates travel rounded to 0.1 mm.
_DECIMALS = 4


def _point(point):
    return [round(float(point[0]), _DECIMALS), round(float(point[1]), _DECIMALS)]


def _rgb(rgb):
    return None if rgb is None else [int(channel) for channel in rgb]


_DATA = {
    FilledPolygon: lambda p: {"rings": [[_point(point) for point in ring] for ring in p.rings], "rgb": _rgb(p.rgb)},
    Polyline: lambda p: {**_fields(p), "points": [_point(point) for point in p.points], "rgb": _rgb(p.rgb)},
    Disc: lambda p: {**_fields(p), "center": _point(p.center), "rgb": _rgb(p.rgb)},
    Text: lambda p: {**_fields(p), "position": _point(p.position), "rgb": _rgb(p.rgb)},
    Image: _image_data,
}


def _rings_extent(primitive):
    return np.vstack(primitive.rings)


def _image_corners(image):
    (sx, sy), yaw = image.size, np.radians(image.yaw_deg)
    corners = np.array(((-sx, -sy), (sx, -sy), (sx, sy), (-sx, sy))) / 2.0
    rotation = np.array(((np.cos(yaw), np.sin(yaw)), (-np.sin(yaw), np.cos(yaw))))
    return corners @ rotation + image.center


# Points whose bounding box contains each kind of primitive (a stroke's half width and a text's size aside).
_EXTENT_POINTS = {
    FilledPolygon: _rings_extent,
    Polyline: lambda p: np.asarray(p.points, dtype=float),
    Disc: lambda p: np.asarray(p.center) + np.array(((-p.radius, -p.radius), (p.radius, p.radius))),
    Text: lambda p: np.asarray([p.position], dtype=float),
    Image: _image_corners,
}


def primitives_extent(primitives):
    """(x_min, y_min, x_max, y_max) over `primitives`, or None if there are none."""
    if not primitives:
        return None
    points = np.vstack([_EXTENT_POINTS[type(p)](p) for p in primitives])
    return (*points.min(axis=0), *points.max(axis=0))


def to_data(primitive):
    """{"kind": class name, ...fields} with lists for tuples, ready for JSON."""
    return {"kind": type(primitive).__name__, **_DATA[type(primitive)](primitive)}
