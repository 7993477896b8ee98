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
    return {"src": "data:image/png;base64," + base64.b64encode(png).decode("ascii"), "center": list(image.center),
            "size": list(image.size), "yaw_deg": image.yaw_deg}


def _fields(primitive):
    return {name: getattr(primitive, name) for name in primitive.__dataclass_fields__}


_DATA = {
    FilledPolygon: lambda p: {"rings": [[list(point) for point in ring] for ring in p.rings], "rgb": list(p.rgb)},
    Polyline: lambda p: {**_fields(p), "points": [list(point) for point in p.points], "rgb": list(p.rgb)},
    Disc: lambda p: {**_fields(p), "center": list(p.center), "rgb": list(p.rgb)},
    Text: lambda p: {**_fields(p), "position": list(p.position), "rgb": list(p.rgb)},
    Image: _image_data,
}


def to_data(primitive):
    """{"kind": class name, ...fields} with lists for tuples, ready for JSON."""
    return {"kind": type(primitive).__name__, **_DATA[type(primitive)](primitive)}
