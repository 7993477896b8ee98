"""What the page draws of tb3_sim's world, as plain data: the world (from /gazebo/world_markers), the robot's
trail and the newest LiDAR sweep in the world frame. No ROS import: the bridge passes message fields in.

Coordinates are metres in the world (odom) frame, rounded to millimetres to keep frames small.
"""
import json
import math
from collections import deque
from typing import Iterable, List, NamedTuple, Optional, Sequence, Tuple

EMPTY_WORLD_HALF_SIZE_M = 3.0
"""An empty world is shown as 6 x 6 m around the origin."""
VIEW_MARGIN_M = 0.5
TRAIL_STEP_M = 0.02
"""A trail point every 2 cm travelled."""
TRAIL_JUMP_M = 0.5
"""A move this long between two states is a reset or teleport, not driving: the trail starts again."""
TRAIL_MAX_POINTS = 3000

# visualization_msgs/Marker types and actions used by tb3_sim's world markers.
CUBE, CYLINDER, LINE_LIST, TRIANGLE_LIST = 1, 3, 5, 11
ADD = 0


def _mm(value):
    return round(value, 3)


class Pose2D(NamedTuple):
    x: float
    y: float
    yaw: float


def yaw_of(qz, qw):
    """Heading of a quaternion that only rotates about z."""
    return 2.0 * math.atan2(qz, qw)


class MarkerData(NamedTuple):
    """The fields of one visualization_msgs/Marker the scene uses."""

    ns: str
    type: int
    action: int
    pose: Pose2D
    scale_x: float
    scale_y: float
    points: Tuple[Tuple[float, float], ...]
    text: str


def _polygons(points):
    """A TRIANGLE_LIST's triangles as polygons: one polygon when they fan out from one vertex (how tb3_sim draws a
    convex wall's top face), so the page fills it without seams along the inner edges."""
    triangles = [points[i:i + 3] for i in range(0, len(points) - 2, 3)]
    fan = all(triangle[0] == triangles[0][0] for triangle in triangles) and all(
        before[2] == after[1] for before, after in zip(triangles, triangles[1:]))
    if triangles and fan:
        triangles = [[triangles[0][0], triangles[0][1]] + [triangle[2] for triangle in triangles]]
    return [{"kind": "polygon", "points": [[_mm(x), _mm(y)] for x, y in triangle]} for triangle in triangles]


def _shape_of_static(marker):
    if marker.type == TRIANGLE_LIST:
        return _polygons(marker.points)
    if marker.type == LINE_LIST:
        return [{"kind": "segment", "points": [[_mm(x), _mm(y)] for x, y in marker.points[i:i + 2]]}
                for i in range(0, len(marker.points) - 1, 2)]
    if marker.type == CYLINDER:
        return [{"kind": "circle", "x": _mm(marker.pose.x), "y": _mm(marker.pose.y), "r": _mm(marker.scale_x / 2.0)}]
    return []


def _model_of(marker):
    model = {"name": marker.text, "x": _mm(marker.pose.x), "y": _mm(marker.pose.y), "yaw": round(marker.pose.yaw, 4)}
    if marker.type == CYLINDER:
        model.update(kind="circle", r=_mm(marker.scale_x / 2.0))
    else:
        model.update(kind="box", sx=_mm(marker.scale_x), sy=_mm(marker.scale_y))
    return model


def _extent(world):
    xs, ys = [], []
    for shape in world["static"]:
        if shape["kind"] == "circle":
            xs += [shape["x"] - shape["r"], shape["x"] + shape["r"]]
            ys += [shape["y"] - shape["r"], shape["y"] + shape["r"]]
        else:
            xs += [x for x, _ in shape["points"]]
            ys += [y for _, y in shape["points"]]
    for model in world["models"] + world["robots"]:
        xs.append(model["x"])
        ys.append(model["y"])
    if not xs:
        return [-EMPTY_WORLD_HALF_SIZE_M, -EMPTY_WORLD_HALF_SIZE_M, EMPTY_WORLD_HALF_SIZE_M, EMPTY_WORLD_HALF_SIZE_M]
    return [_mm(min(xs) - VIEW_MARGIN_M), _mm(min(ys) - VIEW_MARGIN_M),
            _mm(max(xs) + VIEW_MARGIN_M), _mm(max(ys) + VIEW_MARGIN_M)]


def world_content(markers: Iterable[MarkerData]):
    """The `world` frame's content from one MarkerArray of tb3_sim's /gazebo/world_markers: static shapes
    (namespace "static"), models ("models") and robot bodies ("robots"). A DELETEALL marker comes first in
    each array, so each array is the whole world.

    The bounds fit the static shapes only (plus the models when there are none), so the view does not move
    when a box is dragged; EMPTY_WORLD_HALF_SIZE_M around the origin for an empty world."""
    world = {"static": [], "models": [], "robots": []}
    for marker in markers:
        if marker.action != ADD:
            continue
        if marker.ns == "static":
            world["static"].extend(_shape_of_static(marker))
        elif marker.ns in ("models", "robots"):
            world[marker.ns].append(_model_of(marker))
    bounds_source = {"static": world["static"], "models": [] if world["static"] else world["models"], "robots": []}
    world["bounds"] = _extent(bounds_source)
    return world


def scan_points(ranges: Sequence[float], angle_min, angle_increment, range_min, range_max,
                sensor: Pose2D) -> List[List[float]]:
    """World-frame [x, y] of each LiDAR return within (range_min, range_max), the sensor at `sensor`."""
    points = []
    for i, distance in enumerate(ranges):
        if not range_min <= distance < range_max:   # inf, nan and out-of-range readings are no hit
            continue
        angle = sensor.yaw + angle_min + i * angle_increment
        points.append([_mm(sensor.x + distance * math.cos(angle)), _mm(sensor.y + distance * math.sin(angle))])
    return points


def compose(base: Pose2D, offset: Pose2D) -> Pose2D:
    """`offset` (given in `base`'s frame) in the frame `base` is given in."""
    cos_yaw, sin_yaw = math.cos(base.yaw), math.sin(base.yaw)
    return Pose2D(base.x + cos_yaw * offset.x - sin_yaw * offset.y,
                  base.y + sin_yaw * offset.x + cos_yaw * offset.y, base.yaw + offset.yaw)


def sensor_offset(static_transforms, base_frame, sensor_frame):
    """Pose2D of `sensor_frame` in `base_frame` from fixed transforms {child: (parent, Pose2D in the parent)}
    (/tf_static), or None when no chain of them leads from the base to the sensor."""
    chain = []
    frame = sensor_frame
    while frame != base_frame:
        if frame not in static_transforms or len(chain) > len(static_transforms):
            return None
        parent, pose = static_transforms[frame]
        chain.append(pose)
        frame = parent
    offset = Pose2D(0.0, 0.0, 0.0)
    for pose in reversed(chain):
        offset = compose(offset, pose)
    return offset


class Trail:
    """The robot's path: a point every TRAIL_STEP_M, at most TRAIL_MAX_POINTS (the oldest dropped); a jump of
    TRAIL_JUMP_M or more (reset_world, set_model_state) starts a new trail.

    Pages get it incrementally: `since(cursor)` gives what a page holding `cursor` lacks, so a state frame
    carries a few new points rather than the whole path."""

    def __init__(self):
        self._points = deque(maxlen=TRAIL_MAX_POINTS)
        self._generation = 0
        self._added = 0

    def add(self, x, y):
        """Record the robot at (x, y)."""
        if self._points:
            last_x, last_y = self._points[-1]
            step = math.hypot(x - last_x, y - last_y)
            if step >= TRAIL_JUMP_M:
                self.clear()
            elif step < TRAIL_STEP_M:
                return
        self._points.append([_mm(x), _mm(y)])
        self._added += 1

    def clear(self):
        """Start a new trail (another robot is followed, or this one jumped): pages replace theirs."""
        self._points.clear()
        self._generation += 1
        self._added = 0

    def since(self, cursor):
        """(reset, points, new cursor) for a page that holds the trail up to `cursor` (None: nothing yet).
        reset True: the page replaces its trail with `points`; False: it appends them."""
        now = (self._generation, self._added)
        if cursor is not None and cursor[0] == self._generation and self._added - cursor[1] <= len(self._points):
            new = self._added - cursor[1]
            return False, list(self._points)[len(self._points) - new:] if new else [], now
        return True, list(self._points), now


def robot_state(pose: Optional[Pose2D], linear, angular):
    """The `state` frame's robot entry, or None without a robot."""
    if pose is None:
        return None
    return {"x": _mm(pose.x), "y": _mm(pose.y), "yaw": round(pose.yaw, 4), "v": round(linear, 3),
            "w": round(angular, 3)}


# The scene description tb3_sim publishes is trusted local data, but still bounded.
MAX_SCENE_CHARS = 32 * 1024 * 1024


def scene_primitives(text):
    """The list of drawing primitives of /gazebo/scene_primitives' JSON `text` (tb3_sim.core.primitives.to_data),
    or None when it is not a JSON list of objects with a "kind" (the page then draws the static shapes of the
    markers)."""
    if len(text) > MAX_SCENE_CHARS:
        return None
    try:
        primitives = json.loads(text)
    except ValueError:
        return None
    if not isinstance(primitives, list) or not all(isinstance(p, dict) and "kind" in p for p in primitives):
        return None
    return primitives


def _scene_points(primitive):
    points = [point for ring in primitive.get("rings", []) for point in ring] + list(primitive.get("points", []))
    for key in ("center", "position"):
        if key in primitive:
            points.append(primitive[key])
    return points


def with_scene_bounds(content, primitives):
    """The `world` frame content with its bounds widened to take in the floor and static shapes the scene
    primitives draw (a floor often reaches past the walls). The primitives go to the page in a frame of their own,
    once, not with each world frame."""
    content = dict(content)
    points = [point for primitive in primitives or [] for point in _scene_points(primitive)]
    if points:
        x_min, y_min, x_max, y_max = content["bounds"]
        xs, ys = [p[0] for p in points], [p[1] for p in points]
        if content["static"] or content["models"]:
            xs, ys = xs + [x_min + VIEW_MARGIN_M, x_max - VIEW_MARGIN_M], ys + [y_min + VIEW_MARGIN_M,
                                                                                 y_max - VIEW_MARGIN_M]
        content["bounds"] = [_mm(min(xs) - VIEW_MARGIN_M), _mm(min(ys) - VIEW_MARGIN_M),
                             _mm(max(xs) + VIEW_MARGIN_M), _mm(max(ys) + VIEW_MARGIN_M)]
    return content
