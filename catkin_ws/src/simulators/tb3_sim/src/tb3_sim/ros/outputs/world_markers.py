"""The world as a visualization_msgs/MarkerArray, so `rviz -d $(rospack find tb3_sim)/rviz/tb3_sim.rviz`
shows the obstacles beside /scan and TF, also where no robot_description is loaded to draw a RobotModel from.

Static walls and pillars (namespace "static"), the models with their current poses ("models") and each robot's
base collision box ("robots"), all in the odom frame, which is the world frame here (a single robot's odom;
with several robots, each robot's prefixed odom coincides with it too).
Published on `~world_markers` (/gazebo/world_markers), latched at start and again at MARKER_RATE_HZ (sim time)
while someone subscribes, so moved, spawned and deleted models show up.
"""
import math
from typing import NamedTuple, Tuple

from geometry_msgs.msg import Point
from visualization_msgs.msg import Marker, MarkerArray

from tb3_sim.core.shapes import Box, Polygon, Segment
from tb3_sim.core.turtlebot3 import BASE_JOINT_Z_M
from tb3_sim.ros import messages
from tb3_sim.ros.outputs.output import Output, Topic

MARKER_RATE_HZ = 2.0

FRAME_ID = "odom"
STATIC_RGBA = (0.5, 0.5, 0.5, 1.0)
MODEL_RGBA = (0.69, 0.47, 0.25, 1.0)
ROBOT_RGBA = (0.12, 0.24, 0.55, 0.8)
SEGMENT_WIDTH_M = 0.03


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


def _robot_marker(robot, marker_id, stamp):
    """The base box of `robot` (a MarkedModel whose shape is a turtlebot3.TurtleBot3Model), standing on the floor
    from base_link's height (1 cm) up to the top of its base."""
    model, pose = robot.shape, robot.pose
    marker = _marker("robots", marker_id, Marker.CUBE, ROBOT_RGBA, stamp)
    marker.text = robot.name
    centre_x = (model.body_x_min_m + model.body_x_max_m) / 2.0
    x, y = pose.compose(centre_x, 0.0)
    _place(marker, x, y, pose.yaw, model.body_top_m - BASE_JOINT_Z_M)
    marker.pose.position.z += BASE_JOINT_Z_M
    marker.scale.x = model.body_x_max_m - model.body_x_min_m
    marker.scale.y = 2.0 * model.body_half_width_m
    marker.scale.z = model.body_top_m - BASE_JOINT_Z_M
    return marker


def world_markers(static_shapes, models, robots, stamp):
    """A MarkerArray: DELETEALL first (so deleted models disappear), then the static shapes, the models
    (MarkedModel: `name`, `shape` (Box or Cylinder) and `pose` (Pose2D)) and the robots' bodies (MarkedModel with
    the robot's TurtleBot3Model as `shape`)."""
    clear = Marker()
    clear.action = Marker.DELETEALL
    markers = [clear]
    markers.extend(_static_marker(shape, i, stamp) for i, shape in enumerate(static_shapes))
    markers.extend(_model_marker(model, i, stamp) for i, model in enumerate(models))
    markers.extend(_robot_marker(robot, i, stamp) for i, robot in enumerate(robots))
    return MarkerArray(markers=markers)


class MarkedModel(NamedTuple):
    """What a model marker shows: its name, shape (Box or Cylinder, or a robot's TurtleBot3Model) and world
    pose."""

    name: str
    shape: object
    pose: object


class WorldReading(NamedTuple):
    static_shapes: Tuple
    models: Tuple[MarkedModel, ...]
    robots: Tuple[MarkedModel, ...]
    time_s: float


class WorldMarkersOutput(Output):
    rate_hz = MARKER_RATE_HZ
    lazy = True
    frame_ids = (FRAME_ID,)

    def __init__(self):
        super().__init__()
        self.topics = (Topic("~world_markers", MarkerArray, self._markers, latch=True),)

    def read(self, world, now_s, wanted):
        models = tuple(MarkedModel(m.name, m.spec.shape, m.pose) for m in world.models())
        robots = tuple(MarkedModel(r.name, r.model, r.pose) for r in world.robots())
        return WorldReading(world.description.static_shapes, models, robots, now_s)

    @staticmethod
    def _markers(reading):
        return world_markers(reading.static_shapes, reading.models, reading.robots, messages.stamp(reading.time_s))
