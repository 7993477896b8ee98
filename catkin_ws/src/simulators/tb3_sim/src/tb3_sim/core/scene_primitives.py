"""One description of the scene for every view: the floor, its markings, static shapes and models turned into
drawing primitives (core.primitives) by ONE table of converters, CONVERTERS, keyed by the kind of thing. A new kind
of marking or shape is one converter and one row here; every view (the Qt window and demo PNG, the browser page,
the grader's pictures) and the camera's floor texture then draw it.

Curves are flattened here, once, into polylines whose chords stray at most FLATNESS_M from the true curve; dashes
become separate polylines; arrowheads become filled triangles (base as wide as the head is long) whose tip is the
path's end, with the stroke cut back under the head so that its butt end does not show beside the tip.
"""

import math

import numpy as np

from tb3_sim.core.floor import (
    ArcMarking,
    CircleMarking,
    CurveMarking,
    Floor,
    FloorImage,
    PolygonMarking,
    PolylineMarking,
    RectangleMarking,
    TextMarking,
)
from tb3_sim.core.geometry import Pose2D
from tb3_sim.core.primitives import Disc, FilledPolygon, Image, Polyline, Text
from tb3_sim.core.shapes import Box, Circle, Cylinder, Polygon, Segment

# Largest distance between a flattened arc or Bézier and its chords, metres.
FLATNESS_M = 0.0005
# Top-down views draw zero-thickness walls this wide.
SEGMENT_WIDTH_M = 0.03
ARROW_HALF_WIDTH_PER_LENGTH = 0.5
_MAX_ARC_STEPS = 720


def primitives_of(thing, default_rgb=None):
    """The primitives of a floor, a floor marking, a static shape or a placed model ((shape, pose, rgb)); a shape
    without its own colour takes `default_rgb`."""
    return CONVERTERS[type(thing)](thing, default_rgb)


def scene_primitives(floor, static_shapes=(), static_rgb=None):
    """The primitives of a world's fixed part, in painting order: the floor (if any), then the static shapes."""
    parts = primitives_of(floor) if floor is not None else []
    for shape in static_shapes:
        parts.extend(primitives_of(shape, static_rgb))
    return parts


def model_primitives(shape, pose, rgb):
    """The primitives of a model's Box or Cylinder at `pose` (world), coloured `rgb`."""
    return CONVERTERS[type(shape)]((shape, pose), rgb)


def _floor(floor, _default):
    x0, y0, x1, y1 = floor.bounds()
    parts = [FilledPolygon((((x0, y0), (x1, y0), (x1, y1), (x0, y1)),), floor.rgb)]
    if floor.image is not None:
        parts.extend(primitives_of(floor.image))
    for marking in floor.markings:
        parts.extend(primitives_of(marking))
    return parts


def _floor_image(image, _default):
    return [Image(image.pixels, image.center, image.size, image.yaw_deg)]


def _outline_or_fill(ring, marking):
    """A closed shape: filled, or only its stroke (dashed if asked) when the marking has one."""
    if marking.stroke is None:
        return [FilledPolygon((tuple(ring),), marking.rgb)]
    return _stroke(ring, marking, closed=True)


def _rectangle(marking, _default):
    (sx, sy), pose = marking.size, Pose2D(*marking.center, math.radians(marking.yaw_deg))
    return _outline_or_fill([pose.compose(x, y) for x, y in Box(sx, sy, 0.0).corners()], marking)


def _polygon(marking, _default):
    return _outline_or_fill(marking.points, marking)


def _circle(marking, _default):
    if marking.stroke is None:
        return [Disc(marking.center, marking.radius, marking.rgb)]
    ring = arc_points(marking.center, marking.radius, 0.0, 2.0 * math.pi)[:-1]
    return _stroke(ring, marking, closed=True)


def _arc(marking, _default):
    start = math.radians(marking.start_deg)
    sweep = math.radians((marking.end_deg - marking.start_deg) % 360.0)
    return _stroke(arc_points(marking.center, marking.radius, start, sweep), marking)


def _polyline(marking, _default):
    return _stroke(marking.points, marking, closed=marking.closed)


def _curve(marking, _default):
    return _stroke(bezier_points(marking.points), marking)


def _text(marking, _default):
    return [Text(marking.text, marking.position, marking.height, marking.angle_deg, marking.bold, marking.rgb)]


def _segment(shape, default_rgb):
    return [Polyline((shape.start, shape.end), SEGMENT_WIDTH_M, shape.rgb or default_rgb)]


def _static_polygon(shape, default_rgb):
    return [FilledPolygon((shape.points,), shape.rgb or default_rgb)]


def _static_circle(shape, default_rgb):
    return [Disc(shape.center, shape.radius, shape.rgb or default_rgb)]


def _box(placed, rgb):
    box, pose = placed
    return [FilledPolygon((tuple(pose.compose(x, y) for x, y in box.corners()),), rgb)]


def _cylinder(placed, rgb):
    cylinder, pose = placed
    return [Disc((pose.x, pose.y), cylinder.radius, rgb)]


CONVERTERS = {
    Floor: _floor,
    FloorImage: _floor_image,
    RectangleMarking: _rectangle,
    PolygonMarking: _polygon,
    CircleMarking: _circle,
    ArcMarking: _arc,
    PolylineMarking: _polyline,
    CurveMarking: _curve,
    TextMarking: _text,
    Segment: _segment,
    Polygon: _static_polygon,
    Circle: _static_circle,
    Box: _box,
    Cylinder: _cylinder,
}


def _stroke(points, marking, closed=False):
    """Polylines (and an arrowhead) for the stroke of `marking` along `points`."""
    stroke = marking.stroke
    points = np.asarray(points, dtype=float)
    parts = []
    if stroke.arrow is not None:
        if stroke.arrow == "start":
            points = points[::-1]
        tip, direction = points[-1], _end_direction(points)
        points = _trim_end(points, min(stroke.arrow_length / 2.0, _length(points) / 2.0))
        parts.append(_arrowhead(tip, direction, stroke.arrow_length, marking.rgb))
    if closed:
        points = np.vstack((points, points[:1]))
    if stroke.dash is None:
        lines = [(points[:-1], True)] if closed else [(points, False)]
    else:
        lines = [(dash, False) for dash in dashes(points, *stroke.dash)]
    strokes = [Polyline(tuple(map(tuple, line)), stroke.width, marking.rgb, is_closed) for line, is_closed in lines]
    return strokes + parts


def _arrowhead(tip, direction, length, rgb):
    base = tip - direction * length
    normal = np.array((-direction[1], direction[0])) * length * ARROW_HALF_WIDTH_PER_LENGTH
    return FilledPolygon(((tuple(tip), tuple(base + normal), tuple(base - normal)),), rgb)


def _end_direction(points):
    """Unit direction of the path at its last point (from the last distinct point before it)."""
    for earlier in points[-2::-1]:
        step = points[-1] - earlier
        norm = math.hypot(*step)
        if norm > 0.0:
            return step / norm
    return np.array((1.0, 0.0))


def _length(points):
    return float(np.hypot(*np.diff(points, axis=0).T).sum())


def _trim_end(points, cut):
    """`points` with its last `cut` metres of length removed."""
    return _cut(points, 0.0, _length(points) - cut)


def _cut(points, start, end):
    """The part of the polyline `points` between arc lengths `start` and `end` (metres from its first point)."""
    steps = np.hypot(*np.diff(points, axis=0).T)
    along = np.concatenate(([0.0], np.cumsum(steps)))
    inside = points[(along > start) & (along < end)]
    return np.vstack(([_point_at(points, along, start)], inside, [_point_at(points, along, end)]))


def _point_at(points, along, distance):
    i = int(np.clip(np.searchsorted(along, distance, side="right") - 1, 0, len(points) - 2))
    span = along[i + 1] - along[i]
    t = 0.0 if span == 0.0 else (distance - along[i]) / span
    return points[i] + t * (points[i + 1] - points[i])


def dashes(points, on_m, off_m):
    """The dashes of the polyline `points` (an array) as arrays of points: `on_m` drawn, `off_m` skipped, starting
    with a dash at the first point (SVG's stroke-dasharray with offset 0)."""
    total = _length(points)
    starts = np.arange(0.0, total, on_m + off_m)
    return [_cut(points, start, min(start + on_m, total)) for start in starts]


def arc_points(center, radius, start_rad, sweep_rad):
    """Points along the circle of `radius` about `center` from `start_rad` anticlockwise by `sweep_rad`, both ends
    included, chords within FLATNESS_M of the arc."""
    step = 2.0 * math.acos(max(-1.0, 1.0 - FLATNESS_M / radius)) if radius > FLATNESS_M else math.pi / 2
    count = int(min(_MAX_ARC_STEPS, max(2, math.ceil(abs(sweep_rad) / step))))
    angles = start_rad + np.linspace(0.0, sweep_rad, count + 1)
    return np.column_stack((center[0] + radius * np.cos(angles), center[1] + radius * np.sin(angles)))


def bezier_points(points):
    """The chain of cubic Béziers p0, c1, c2, p1, ... flattened: each piece sampled finely enough that the chords
    stay within FLATNESS_M (from the bound on the second derivative: n >= sqrt(max |B''| / (8 flatness)))."""
    control = np.asarray(points, dtype=float)
    pieces = [control[0:1]]
    for k in range(0, len(control) - 1, 3):
        p0, c1, c2, p1 = control[k:k + 4]
        bend = max(np.hypot(*(6.0 * (p0 - 2.0 * c1 + c2))), np.hypot(*(6.0 * (c1 - 2.0 * c2 + p1))))
        count = int(min(_MAX_ARC_STEPS, max(1, math.ceil(math.sqrt(bend / (8.0 * FLATNESS_M))))))
        t = np.linspace(0.0, 1.0, count + 1)[1:, None]
        pieces.append((1 - t) ** 3 * p0 + 3 * (1 - t) ** 2 * t * c1 + 3 * (1 - t) * t ** 2 * c2 + t ** 3 * p1)
    return np.vstack(pieces)
