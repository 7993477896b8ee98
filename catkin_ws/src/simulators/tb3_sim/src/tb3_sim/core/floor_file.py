"""The `floor:` section of a world file, checked key by key into a floor.Floor (format in world_file's docstring).

Each marking kind is one row of MARKING_KINDS: its keys (True = required) and the function that builds it, so a
new kind is one function and one row. Errors go through the world file's reader, so they name the file and the
key (e.g. `floor.markings[3].width`). Untrusted input is bounded: at most MAX_MARKINGS markings of at most
MAX_MARKING_POINTS points (MAX_POLYGON_POINTS for a polygon) and MAX_DASHES dashes, texts of at most
MAX_TEXT_CHARS characters, images of at most MAX_IMAGE_SIDE_PX pixels a side and MAX_IMAGE_BYTES bytes.
"""

import math
import struct
from pathlib import Path

import numpy as np

from tb3_sim.core.floor import (
    ARROW_ENDS,
    DEFAULT_ARROW_LENGTH_WIDTHS,
    ArcMarking,
    CircleMarking,
    CurveMarking,
    Floor,
    FloorImage,
    PolygonMarking,
    PolylineMarking,
    RectangleMarking,
    Stroke,
    TextMarking,
)

MAX_MARKINGS = 10000
MAX_MARKING_POINTS = 2000
# A polygon's simplicity check compares every pair of edges.
MAX_POLYGON_POINTS = 500
MAX_TEXT_CHARS = 200
MAX_DASHES = 20000
MAX_IMAGE_SIDE_PX = 4096
MAX_IMAGE_BYTES = 64 * 1024 * 1024
DEFAULT_FLOOR_COLOUR = "white"

_FLOOR_KEYS = {"size": True, "center": False, "color": False, "image": False, "markings": False}
_IMAGE_KEYS = {"file": True, "center": False, "size": True, "yaw_deg": False}
_STROKE_KEYS = {"width": False, "dash": False}
_ARROW_KEYS = {"arrow": False, "arrow_length": False}


def parse_floor(reader, value, key, base_dir):
    """The Floor of the mapping `value` at `key`; `base_dir` is where the image path is relative to."""
    reader.keys(value, key, _FLOOR_KEYS)
    size = reader.numbers(value["size"], f"{key}.size", 2, positive=True)
    center = reader.numbers(value.get("center", [0.0, 0.0]), f"{key}.center", 2)
    rgb = reader.colour({"color": value.get("color", DEFAULT_FLOOR_COLOUR)}, key)
    image = _image(reader, value["image"], f"{key}.image", base_dir) if "image" in value else None
    items = reader.list(value.get("markings", []), f"{key}.markings")
    if len(items) > MAX_MARKINGS:
        reader.fail(f"{key}.markings", f"at most {MAX_MARKINGS} markings, got {len(items)}")
    markings = tuple(_marking(reader, item, f"{key}.markings[{i}]") for i, item in enumerate(items))
    return Floor(size, center, rgb, image, markings)


def _marking(reader, item, key):
    kind = reader.kind(item, key, {kind: keys for kind, (keys, _) in MARKING_KINDS.items()})
    marking = MARKING_KINDS[kind][1](_Item(reader, item, key))
    stroke = getattr(marking, "stroke", None)
    if stroke is not None and stroke.dash is not None:
        dashes = _PATH_LENGTH[type(marking)](marking) / sum(stroke.dash)
        if dashes > MAX_DASHES:
            reader.fail(f"{key}.dash", f"{dashes:.0f} dashes along this path; at most {MAX_DASHES}")
    return marking


def _polyline_length(points, closed=False):
    path = np.asarray(points + (points[0],) if closed else points, dtype=float)
    return float(np.hypot(*np.diff(path, axis=0).T).sum())


# Length of each stroked path in metres (for a curve, of its control polygon, which is never shorter).
_PATH_LENGTH = {
    RectangleMarking: lambda m: 2.0 * (m.size[0] + m.size[1]),
    PolygonMarking: lambda m: _polyline_length(m.points, closed=True),
    CircleMarking: lambda m: 2.0 * math.pi * m.radius,
    ArcMarking: lambda m: m.radius * math.radians((m.end_deg - m.start_deg) % 360.0),
    PolylineMarking: lambda m: _polyline_length(m.points, m.closed),
    CurveMarking: lambda m: _polyline_length(m.points),
}


class _Item:
    """One marking's mapping with typed getters that name `key.<field>` in errors."""

    def __init__(self, reader, item, key):
        self.reader, self.item, self.key = reader, item, key

    def at(self, field):
        return f"{self.key}.{field}"

    def point(self, field):
        return self.reader.numbers(self.item[field], self.at(field), 2)

    def number(self, field, default=None, positive=False):
        return self.reader.number(self.item.get(field, default), self.at(field), positive)

    def flag(self, field, default):
        value = self.item.get(field, default)
        if not isinstance(value, bool):
            self.reader.fail(self.at(field), f"expected true or false, got {value!r}")
        return value

    def colour(self):
        return self.reader.colour(self.item, self.key)

    def points(self, minimum, maximum=MAX_MARKING_POINTS):
        value, where = self.item["points"], self.at("points")
        if not isinstance(value, list) or not minimum <= len(value) <= maximum:
            self.reader.fail(where, f"expected a list of {minimum} to {maximum} [x, y] points, got {_short(value)}")
        return tuple(self.reader.numbers(p, f"{where}[{i}]", 2) for i, p in enumerate(value))

    def stroke(self, required, arrow=False):
        """The Stroke of the `width`/`dash`/`arrow` keys, or None when `width` is absent and not `required`."""
        if "width" not in self.item:
            if required:
                self.reader.fail(self.at("width"), "missing required key")
            for field in ("dash", "arrow", "arrow_length"):
                if field in self.item:
                    self.reader.fail(self.at(field), "only with `width` (a stroke)")
            return None
        width = self.number("width", positive=True)
        dash = None
        if "dash" in self.item:
            dash = self.reader.numbers(self.item["dash"], self.at("dash"), 2, positive=True)
        end, length = None, 0.0
        if arrow and "arrow" in self.item:
            end = self.item["arrow"]
            if end not in ARROW_ENDS:
                self.reader.fail(self.at("arrow"), f"expected one of {', '.join(ARROW_ENDS)}, got {end!r}")
            length = self.number("arrow_length", DEFAULT_ARROW_LENGTH_WIDTHS * width, positive=True)
        elif "arrow_length" in self.item:
            self.reader.fail(self.at("arrow_length"), "only with `arrow`")
        return Stroke(width, dash, end, length)


def _rectangle(item):
    return RectangleMarking(item.point("center"), item.reader.numbers(item.item["size"], item.at("size"), 2, True),
                            item.number("yaw_deg", 0.0), item.colour(), item.stroke(required=False))


def _polygon(item):
    points = item.points(3, MAX_POLYGON_POINTS)
    if not _is_simple(points):
        item.reader.fail(item.at("points"), "polygon must be simple: its edges may not cross or overlap")
    return PolygonMarking(points, item.colour(), item.stroke(required=False))


def _circle(item):
    return CircleMarking(item.point("center"), item.number("radius", positive=True), item.colour(),
                         item.stroke(required=False))


def _arc(item):
    start, end = item.number("start_deg"), item.number("end_deg")
    if math.isclose(math.remainder(end - start, 360.0), 0.0, abs_tol=1e-9):
        item.reader.fail(item.at("end_deg"), "the arc has no length (for a full ring use a circle with `width`)")
    return ArcMarking(item.point("center"), item.number("radius", positive=True), start, end, item.colour(),
                      item.stroke(required=True, arrow=True))


def _polyline(item):
    closed = item.flag("closed", False)
    points = item.points(3 if closed else 2)
    if closed and "arrow" in item.item:
        item.reader.fail(item.at("arrow"), "a closed polyline has no ends for an arrow")
    return PolylineMarking(points, closed, item.colour(), item.stroke(required=True, arrow=True))


def _curve(item):
    points = item.points(4)
    if (len(points) - 1) % 3:
        item.reader.fail(item.at("points"), f"expected 3n + 1 points (start, then control, control, end per "
                                            f"Bézier), got {len(points)}")
    return CurveMarking(points, item.colour(), item.stroke(required=True, arrow=True))


def _text(item):
    text = item.item["text"]
    if not isinstance(text, str) or not text.strip() or len(text) > MAX_TEXT_CHARS or not text.isprintable():
        item.reader.fail(item.at("text"), f"expected printable text of 1 to {MAX_TEXT_CHARS} characters, got "
                                          f"{_short(text)}")
    return TextMarking(text, item.point("position"), item.number("height", positive=True),
                       item.number("angle_deg", 0.0), item.flag("bold", False), item.colour())


_COMMON = {"type": True, "color": True}
MARKING_KINDS = {
    "rectangle": ({**_COMMON, "center": True, "size": True, "yaw_deg": False, **_STROKE_KEYS}, _rectangle),
    "polygon": ({**_COMMON, "points": True, **_STROKE_KEYS}, _polygon),
    "circle": ({**_COMMON, "center": True, "radius": True, **_STROKE_KEYS}, _circle),
    "arc": ({**_COMMON, "center": True, "radius": True, "start_deg": True, "end_deg": True, **_STROKE_KEYS,
             **_ARROW_KEYS}, _arc),
    "polyline": ({**_COMMON, "points": True, "closed": False, **_STROKE_KEYS, **_ARROW_KEYS}, _polyline),
    "curve": ({**_COMMON, "points": True, **_STROKE_KEYS, **_ARROW_KEYS}, _curve),
    "text": ({**_COMMON, "text": True, "position": True, "height": True, "angle_deg": False, "bold": False}, _text),
}


def _image(reader, value, key, base_dir):
    reader.keys(value, key, _IMAGE_KEYS)
    file_name = value["file"]
    if not isinstance(file_name, str) or not file_name:
        reader.fail(f"{key}.file", f"expected a file name, got {file_name!r}")
    path = Path(base_dir) / file_name
    try:
        with open(path, "rb") as stream:
            data = stream.read(MAX_IMAGE_BYTES + 1)
    except OSError as error:
        reader.fail(f"{key}.file", f"cannot read {path}: {error.strerror}")
    if len(data) > MAX_IMAGE_BYTES:
        reader.fail(f"{key}.file", f"{path} is larger than {MAX_IMAGE_BYTES // (1024 * 1024)} MB")
    try:
        width, height = image_size(data)
    except ValueError as error:
        reader.fail(f"{key}.file", f"{path}: {error}")
    if max(width, height) > MAX_IMAGE_SIDE_PX:
        reader.fail(f"{key}.file", f"{path} is {width} x {height} px; at most {MAX_IMAGE_SIDE_PX} px a side")
    import cv2  # about 0.4 s: paid only by worlds with a floor image

    bgr = cv2.imdecode(np.frombuffer(data, dtype=np.uint8), cv2.IMREAD_COLOR)
    if bgr is None:
        reader.fail(f"{key}.file", f"{path} cannot be decoded as a PNG or JPEG image")
    return FloorImage(str(path), np.ascontiguousarray(bgr[:, :, ::-1]),
                      reader.numbers(value.get("center", [0.0, 0.0]), f"{key}.center", 2),
                      reader.numbers(value["size"], f"{key}.size", 2, positive=True),
                      reader.number(value.get("yaw_deg", 0.0), f"{key}.yaw_deg"))


_PNG_SIGNATURE = b"\x89PNG\r\n\x1a\n"
_JPEG_START = b"\xff\xd8"
# JPEG start-of-frame markers (baseline, progressive, ...): SOF0-SOF15 except DHT (C4), JPG (C8) and DAC (CC).
_JPEG_FRAME_MARKERS = set(range(0xC0, 0xD0)) - {0xC4, 0xC8, 0xCC}


def image_size(data):
    """(width, height) in pixels from a PNG's IHDR or a JPEG's start-of-frame header, read before any decoding so
    that an oversized image is refused without being unpacked. Raises ValueError for anything else."""
    if data.startswith(_PNG_SIGNATURE) and data[12:16] == b"IHDR":
        return struct.unpack(">II", data[16:24])
    if data.startswith(_JPEG_START):
        offset = 2
        while offset + 9 <= len(data):
            if data[offset] != 0xFF:
                break
            marker = data[offset + 1]
            if marker in _JPEG_FRAME_MARKERS:
                height, width = struct.unpack(">HH", data[offset + 5:offset + 9])
                return width, height
            offset += 2 + struct.unpack(">H", data[offset + 2:offset + 4])[0]
    raise ValueError("not a PNG or JPEG image")


def _is_simple(points):
    """True if no two edges of the closed polygon cross or touch, except neighbours at their shared vertex."""
    p = np.asarray(points, dtype=float)
    a, b = p, np.roll(p, -1, axis=0)
    n = len(p)
    if np.any(np.all(a == b, axis=1)):
        return False

    def side(origin, end, point):
        return np.sign((end[..., 0] - origin[..., 0]) * (point[..., 1] - origin[..., 1])
                       - (end[..., 1] - origin[..., 1]) * (point[..., 0] - origin[..., 0]))

    ai, bi, aj, bj = a[:, None], b[:, None], a[None, :], b[None, :]
    crossing = (side(ai, bi, aj) * side(ai, bi, bj) <= 0) & (side(aj, bj, ai) * side(aj, bj, bi) <= 0)
    # Collinear edges pass the sign test even when apart: keep those only if their boxes overlap.
    boxes_meet = ((np.minimum(ai[..., 0], bi[..., 0]) <= np.maximum(aj[..., 0], bj[..., 0]))
                  & (np.minimum(aj[..., 0], bj[..., 0]) <= np.maximum(ai[..., 0], bi[..., 0]))
                  & (np.minimum(ai[..., 1], bi[..., 1]) <= np.maximum(aj[..., 1], bj[..., 1]))
                  & (np.minimum(aj[..., 1], bj[..., 1]) <= np.maximum(ai[..., 1], bi[..., 1])))
    i, j = np.triu_indices(n, k=2)
    neighbours = (i == 0) & (j == n - 1)
    return not np.any((crossing & boxes_meet)[i, j] & ~neighbours)


def _short(value, limit=60):
    text = repr(value)
    return text if len(text) <= limit else text[:limit] + "..."
