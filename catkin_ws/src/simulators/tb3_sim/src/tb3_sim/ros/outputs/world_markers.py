"""The world as a visualization_msgs/MarkerArray, so `rviz -d $(rospack find tb3_sim)/rviz/tb3_sim.rviz`
shows the obstacles beside /scan and TF (there is no robot_description to draw a RobotModel from).

Static walls and pillars (namespace "static"), the models with their current poses ("models") and the
Waffle's collision box in base_footprint ("robot"), all in the odom frame, which is the world frame here.
Published on `~world_markers` (/gazebo/world_markers), latched at start and again at MARKER_RATE_HZ (sim time)
while someone subscribes, so moved, spawned and deleted models show up.
"""
import math
from typing import NamedTuple, Tuple

from geometry_msgs.msg import Point
from visualization_msgs.msg import Marker, MarkerArray

from tb3_sim.core.shapes import Box, Polygon, Segment
from tb3_sim.core.waffle import WAFFLE_BODY_HALF_WIDTH_M, WAFFLE_BODY_TOP_M, WAFFLE_BODY_X_MAX_M, WAFFLE_BODY_X_MIN_M
from tb3_sim.ros import messages
from tb3_sim.ros.outputs.output import Output, Topic

MARKER_RATE_HZ = 2.0

FRAME_ID = "odom"
STATIC_RGBA = (0.5, 0.5, 0.5, 1.0)
MODEL_RGBA = (0.69, 0.47, 0.25, 1.0)
ROBOT_RGBA = (0.12, 0.24, 0.55, 0.8)
SEGMENT_WIDTH_M = 0.03
BODY_BOTTOM_M = 0.010   # base_link is 1 cm above base_footprint


def _marker(namespace, marker_id, kind, rgba, stamp, frame_id=FRAME_ID):
    marker = Marker()
    marker.header.frame_id = frame_id
    marker.header.stamp = stamp
    marker.ns, marker.id, marker.type, marker.action = namespace, marker_id, kind, Marker.ADD
    marker.color.r, marker.color.g, marker.color.b, marker.color.a = rgba
    marker.pose.orientation.w = 1.0
    return marker


def _place(marker, x, y, yaw, height):
    """Centre a solid of `height` on (x, y) at heading `yaw`, standing on the floor."""
    marker.pose.position.x, marker.pose.position.y, marker.pose.position.z = x, y, height / 2.0
    marker.pose.orientation.z, marker.pose.orientation.w = math.sin(yaw / 2.0), math.cos(yaw / 2.0)


def _static_marker(shape, marker_id, stamp):
    if isinstance(shape, Polygon):   # convex: a fan of triangles makes its top face, at its height
        marker = _marker("static", marker_id, Marker.TRIANGLE_LIST, STATIC_RGBA, stamp)
        first = shape.points[0]
        for second, third in zip(shape.points[1:], shape.points[2:]):
            marker.points.extend(Point(px, py, shape.height) for px, py in (first, second, third))
        marker.scale.x = marker.scale.y = marker.scale.z = 1.0
        return marker
    if isinstance(shape, Segment):
        marker = _marker("static", marker_id, Marker.LINE_LIST, STATIC_RGBA, stamp)
        marker.points = [Point(*shape.start, 0.0), Point(*shape.end, 0.0)]
        marker.scale.x = SEGMENT_WIDTH_M
        return marker
    marker = _marker("static", marker_id, Marker.CYLINDER, STATIC_RGBA, stamp)
    _place(marker, shape.center[0], shape.center[1], 0.0, shape.height)
    marker.scale.x = marker.scale.y = 2.0 * shape.radius
    marker.scale.z = shape.height
    return marker


def _model_marker(model, marker_id, stamp):
    shape = model.shape
    kind = Marker.CUBE if isinstance(shape, Box) else Marker.CYLINDER
    marker = _marker("models", marker_id, kind, MODEL_RGBA, stamp)
    marker.text = model.name
    _place(marker, model.pose.x, model.pose.y, model.pose.yaw, shape.height)
    if isinstance(shape, Box):
        marker.scale.x, marker.scale.y = shape.size_x, shape.size_y
    else:
        marker.scale.x = marker.scale.y = 2.0 * shape.radius
    marker.scale.z = shape.height
    return marker


def _robot_marker(stamp):
    marker = _marker("robot", 0, Marker.CUBE, ROBOT_RGBA, stamp, frame_id="base_footprint")
    marker.pose.position.x = (WAFFLE_BODY_X_MIN_M + WAFFLE_BODY_X_MAX_M) / 2.0
    marker.pose.position.z = (BODY_BOTTOM_M + WAFFLE_BODY_TOP_M) / 2.0
    marker.scale.x = WAFFLE_BODY_X_MAX_M - WAFFLE_BODY_X_MIN_M
    marker.scale.y = 2.0 * WAFFLE_BODY_HALF_WIDTH_M
    marker.scale.z = WAFFLE_BODY_TOP_M - BODY_BOTTOM_M
    return marker


def world_markers(static_shapes, models, stamp):
    """A MarkerArray: DELETEALL first (so deleted models disappear), then the static shapes, the models
    (objects with `name`, `shape` (Box or Cylinder) and `pose` (Pose2D)) and the robot's body."""
    clear = Marker()
    clear.action = Marker.DELETEALL
    markers = [clear]
    markers.extend(_static_marker(shape, i, stamp) for i, shape in enumerate(static_shapes))
    markers.extend(_model_marker(model, i, stamp) for i, model in enumerate(models))
    markers.append(_robot_marker(stamp))
    return MarkerArray(markers=markers)


class MarkedModel(NamedTuple):
    """What a model marker shows: its name, shape (Box or Cylinder) and world pose."""

    name: str
    shape: object
    pose: object


class WorldReading(NamedTuple):
    static_shapes: Tuple
    models: Tuple[MarkedModel, ...]
    time_s: float


class WorldMarkersOutput(Output):
    rate_hz = MARKER_RATE_HZ
    lazy = True
    frame_ids = (FRAME_ID, "base_footprint")

    def __init__(self):
        super().__init__()
        self.topics = (Topic("~world_markers", MarkerArray, self._markers, latch=True),)

    def read(self, world, now_s, wanted):
        models = tuple(MarkedModel(m.name, m.spec.shape, m.pose) for m in world.models())
        return WorldReading(world.description.static_shapes, models, now_s)

    @staticmethod
    def _markers(reading):
        return world_markers(reading.static_shapes, reading.models, messages.stamp(reading.time_s))
