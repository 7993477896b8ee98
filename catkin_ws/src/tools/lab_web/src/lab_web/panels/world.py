"""The world panel: tb3_sim's world from above (/gazebo/world_markers: walls, models, robot bodies; the floor
layer and static shapes as tb3_sim's drawing primitives from /gazebo/scene_primitives, sent once per page and
again only when they change), and the model editing the page offers through tb3_sim's /gazebo services."""
import threading

import rospy
from gazebo_msgs.msg import ModelState
from gazebo_msgs.srv import DeleteModel, GetModelState, SetModelState, SpawnModel
from geometry_msgs.msg import Pose
from std_msgs.msg import String
from std_srvs.srv import Empty
from visualization_msgs.msg import MarkerArray

from lab_web import commands, scene
from lab_web.panels.base import Panel, Versioned
from lab_web.ros_context import BridgeError

MARKERS_TOPIC = "/gazebo/world_markers"
BOX_SIZE_M = 0.3
BOX_SDF = """<?xml version="1.0"?>
<sdf version="1.6"><model name="{name}"><pose>0 0 {half} 0 0 0</pose><link name="link">
<inertial><mass>1.0</mass></inertial>
<collision name="collision"><geometry><box><size>{size} {size} {size}</size></box></geometry></collision>
<visual name="visual"><geometry><box><size>{size} {size} {size}</size></box></geometry></visual>
</link></model></sdf>"""
SIMULATOR = "simulator"
"""The worker pool of the /gazebo requests."""


class WorldPanel(Panel):
    name = "world"
    FRAMES = {
        "world": '{"bounds": [xmin, ymin, xmax, ymax], "static": [shape, ...], "models": [model, ...], '
                 '"robots": [model, ...]}  on connect and whenever it changes (<= 2 Hz). '
                 'shape: {"kind": "polygon", "points": [[x, y], ...]} | {"kind": "segment", "points": [[x, y], '
                 '[x, y]]} | {"kind": "circle", "x", "y", "r"}; model: {"name", "kind": "box" | "circle", "x", "y", '
                 '"yaw", "sx", "sy" (box) | "r" (circle)}; the bounds take in the scene\'s floor',
        "scene": '{"primitives": [primitive, ...]}  tb3_sim\'s /gazebo/scene_primitives as they are (floor layer and '
                 'static shapes), once per page and when they change; drawn instead of the world\'s "static". '
                 'primitive: {"kind": "FilledPolygon", "rings", "rgb"} | {"kind": "Polyline", "points", "width", '
                 '"rgb", "closed"} | {"kind": "Disc", "center", "radius", "rgb"} | {"kind": "Text", "text", '
                 '"position", "height", "angle_deg", "bold", "rgb"} | {"kind": "Image", "src" (PNG data URL), '
                 '"center", "size", "yaw_deg"}; metres, [r, g, b] 0-255 (null: the page\'s wall colour)',
    }
    COMMANDS = {
        "spawn_box": commands.CommandSpec((("x", commands.coordinate()), ("y", commands.coordinate())),
                                          "a 0.3 m box on the floor at (x, y)", SIMULATOR),
        "move_model": commands.CommandSpec((("name", commands.name), ("x", commands.coordinate()),
                                            ("y", commands.coordinate())),
                                           "set_model_state, keeping the model's heading", SIMULATOR),
        "delete_model": commands.CommandSpec((("name", commands.name),), "delete_model", SIMULATOR),
        "reset_world": commands.CommandSpec((), "reset_world", SIMULATOR),
    }

    def __init__(self, ros):
        super().__init__(ros)
        self._lock = threading.Lock()
        self.world = Versioned()
        self.scene = Versioned()
        self._markers_content = None
        self._box_count = 0
        ros.counts(MARKERS_TOPIC)
        self._subscribers = [
            rospy.Subscriber(MARKERS_TOPIC, MarkerArray, self._on_world_markers, queue_size=1),
            rospy.Subscriber("/gazebo/scene_primitives", String, self._on_scene_primitives, queue_size=1),
        ]

    def frames(self, session):
        return self.lacking(session, ("world", self.world), ("scene", self.scene))

    def _on_world_markers(self, array):
        self.ros.count(MARKERS_TOPIC)
        markers = [scene.MarkerData(
            marker.ns, marker.type, marker.action,
            scene.Pose2D(marker.pose.position.x, marker.pose.position.y,
                         scene.yaw_of(marker.pose.orientation.z, marker.pose.orientation.w)),
            marker.scale.x, marker.scale.y, tuple((point.x, point.y) for point in marker.points), marker.text)
            for marker in array.markers]
        with self._lock:
            self._markers_content = scene.world_content(markers)
            self._update_world()

    def _on_scene_primitives(self, message):
        primitives = scene.scene_primitives(message.data)
        with self._lock:
            if primitives is not None and primitives != (self.scene.value or {}).get("primitives"):
                self.scene.set({"primitives": primitives})   # a page gets the scene again only when it changed
            self._update_world()

    def _update_world(self):
        if self._markers_content is None:
            return
        content = scene.with_scene_bounds(self._markers_content, (self.scene.value or {}).get("primitives"))
        if content != self.world.value:
            self.world.set(content)

    def handle(self, session, kind, args):
        return getattr(self, kind)(**args)

    def _model_names(self):
        with self._lock:
            world = self.world.value or {"models": [], "robots": []}
        return {model["name"] for model in world["models"] + world["robots"]}

    def spawn_box(self, x, y):
        taken = self._model_names()
        self._box_count += 1
        while "web_box_{}".format(self._box_count) in taken:
            self._box_count += 1
        name = "web_box_{}".format(self._box_count)
        pose = Pose()
        pose.position.x, pose.position.y, pose.orientation.w = x, y, 1.0
        reply = self.ros.call("/gazebo/spawn_sdf_model", SpawnModel, name,
                              BOX_SDF.format(name=name, size=BOX_SIZE_M, half=BOX_SIZE_M / 2), "", pose, "world")
        if not reply.success:
            raise BridgeError(reply.status_message)
        return "spawned {} at ({:.2f}, {:.2f})".format(name, x, y)

    def move_model(self, name, x, y):
        current = self.ros.call("/gazebo/get_model_state", GetModelState, name, "")
        if not current.success:
            raise BridgeError(current.status_message)
        state = ModelState(model_name=name, pose=current.pose, reference_frame="world")
        state.pose.position.x, state.pose.position.y = x, y
        reply = self.ros.call("/gazebo/set_model_state", SetModelState, state)
        if not reply.success:
            raise BridgeError(reply.status_message)
        return "moved {} to ({:.2f}, {:.2f})".format(name, x, y)

    def delete_model(self, name):
        reply = self.ros.call("/gazebo/delete_model", DeleteModel, name)
        if not reply.success:
            raise BridgeError(reply.status_message)
        return "deleted {}".format(name)

    def reset_world(self):
        self.ros.call("/gazebo/reset_world", Empty)
        return "world reset"
