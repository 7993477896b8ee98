"""The map panel: /map (nav_msgs/OccupancyGrid, latched by gmapping and map_server) as one PNG per new map, and
the fixed frame the page draws in: "map" once a map has come, else "odom" (as RViz with Fixed Frame map shows
nothing useful before SLAM starts, the page falls back to odom). With a map, odom's pose in the map frame comes
from the map -> odom transform on /tf (gmapping and amcl publish it at 20 Hz), and the page places everything the
robot panel and the world panel send (odom-frame data) through it: map -> odom -> base_footprint as in RViz.
The map is the picked robot's own where it publishes one (/tb3_0/map, its SLAM's), else /map (ros_context.
own_or_global); odom is the picked robot's odom frame, with the tf_prefix Gazebo's plugins and tb3_sim give a robot
in a namespace ("tb3_0/odom"; "odom" in the global one). The page keeps the map it shows until the new topic's
(latched) map replaces it."""
import threading

import rospy
from nav_msgs.msg import OccupancyGrid
from tf2_msgs.msg import TFMessage

from lab_web import occupancy, scene
from lab_web.panels.base import Panel, Versioned
from lab_web.ros_context import FollowedSubscribers

TF_STEP_M, TF_STEP_RAD = 0.001, 0.0005
"""A map -> odom change smaller than this is not sent again (it is re-stamped at 20 Hz, mostly unchanged)."""


def odom_frame(namespace):
    """The odom frame of the robot in `namespace` ("" or "/tb3_0"): "odom", or "tb3_0/odom" with its tf_prefix."""
    return "{}/odom".format(namespace.strip("/")) if namespace.strip("/") else "odom"


class MapPanel(Panel):
    name = "map"
    FRAMES = {
        "map": '{"frame": frame_id, "width", "height" (cells), "resolution": m/cell, "origin": [x, y, yaw] (the '
               'lower-left corner of cell (0, 0) in the frame), "png": base64 PNG, a pixel per cell, row 0 first '
               '(the lowest y): unknown (0x70, 0x89, 0x86), free white, occupied black as RViz draws it} | '
               '{"error": why it is not drawn}  on each new /map (gmapping: every 2 s)',
        "fixed": '{"frame": the map\'s frame | "odom", "odom": [x, y, yaw] (odom\'s pose in the fixed frame), '
                 '"odom_frame": the picked robot\'s odom frame}  on connect and when it changes',
    }

    def __init__(self, ros):
        super().__init__(ros)
        self._lock = threading.Lock()
        self.map = Versioned()
        self._map_frame = None
        self._odom_frame = odom_frame(ros.namespace)
        self.fixed = Versioned(self._fixed([0.0, 0.0, 0.0]))
        self._tf_subscribers = []   # from the first map on: before it, odom is the fixed frame and /tf unneeded
        self._followed = FollowedSubscribers(ros, [("map", OccupancyGrid, self._on_map, {
            "queue_size": 1, "buff_size": 2 ** 24})], self._on_switch)
        self._map_topic = self._followed.name("map")
        ros.counts(self._map_topic)
        ros.follow_robot(self._on_robot_picked)

    def _fixed(self, odom):
        return {"frame": self._map_frame or "odom", "odom": odom, "odom_frame": self._odom_frame}

    def on_graph(self, graph):
        self._followed.on_graph(graph)

    def _on_switch(self, _relative, topic):
        """The map comes from another topic now: the graph panel's rate is this one's."""
        self.ros.counts(self._map_topic, on=False)
        self._map_topic = topic
        self.ros.counts(topic)

    def _on_robot_picked(self, _old_namespace):
        """Another robot: its odom frame, placed when map -> odom next comes."""
        with self._lock:
            self._odom_frame = odom_frame(self.ros.namespace)
            self.fixed.set(self._fixed([0.0, 0.0, 0.0]))

    def hello(self):
        """The fixed frame as the page starts: the map's frame once a map has come (its `fixed` frame follows)."""
        with self._lock:
            return {"world_frame": self.fixed.value["frame"]}

    def frames(self, session):
        return self.lacking(session, ("fixed", self.fixed), ("map", self.map))

    def _on_map(self, grid, topic):
        self.ros.count(topic)
        info = grid.info
        origin = info.origin
        try:
            content = {"frame": grid.header.frame_id.lstrip("/") or "map", "width": info.width,
                       "height": info.height, "resolution": info.resolution,
                       "origin": [origin.position.x, origin.position.y,
                                  scene.yaw_of(origin.orientation.z, origin.orientation.w)],
                       "png": occupancy.grid_png(grid.data, info.width, info.height)}
        except ValueError as error:
            content = {"error": "{}: {}".format(topic, error)}
        with self._lock:
            self.map.set(content)
            if "frame" in content and self._map_frame != content["frame"]:
                self._map_frame = content["frame"]
                self.fixed.set(self._fixed([0.0, 0.0, 0.0]))
            if not self._tf_subscribers:
                self._tf_subscribers = [rospy.Subscriber(topic, TFMessage, self._on_tf, queue_size=10)
                                        for topic in ("/tf", "/tf_static")]

    def _on_tf(self, message):
        for stamped in message.transforms:
            if stamped.child_frame_id.lstrip("/") != self._odom_frame:
                continue
            with self._lock:
                if stamped.header.frame_id.lstrip("/") != self._map_frame:
                    continue
                transform = stamped.transform
                odom = [transform.translation.x, transform.translation.y,
                        scene.yaw_of(transform.rotation.z, transform.rotation.w)]
                old = self.fixed.value["odom"]
                if abs(odom[0] - old[0]) >= TF_STEP_M or abs(odom[1] - old[1]) >= TF_STEP_M \
                        or abs(odom[2] - old[2]) >= TF_STEP_RAD:
                    self.fixed.set(self._fixed([round(odom[0], 4), round(odom[1], 4), round(odom[2], 5)]))
