"""The turtlesim panel: every turtlesim/Pose topic (the turtles) and turtlesim's ~canvas/compressed (the pen
trails, when turtlesim runs with ~publish_canvas), found in the master's topic list each graph round."""
import base64
import threading
import time

import roslib.message
import rospy
from sensor_msgs.msg import CompressedImage

from lab_web.panels.base import Panel, Versioned

TURTLE_POSE_TYPE = "turtlesim/Pose"
CANVAS_SUFFIX = "/canvas/compressed"
TURTLE_WORLD_SIZE_M = 500.0 / 45.0
"""turtlesim's 500 px canvas at 45 px per metre."""
DEFAULT_TURTLE_BACKGROUND = (69, 86, 255)


class TurtlesimPanel(Panel):
    name = "turtlesim"
    FRAMES = {
        "turtlesim": '{"stamp_ms", "background": [r, g, b], "turtles": [{"name", "x", "y", "theta"}], '
                     '"size_m": 11.08..., "canvas": true | false (false: turtlesim runs without ~publish_canvas; '
                     'trails cannot be shown)}  with each pose, <= 25 per second',
        "canvas": '{"png": base64 PNG of turtlesim\'s 500x500 pen canvas}  when it changes',
    }

    def __init__(self, ros):
        super().__init__(ros)
        self._lock = threading.Lock()
        self.turtlesim = Versioned()
        self.canvas = Versioned()
        self._turtles = {}
        self._subscribers = {}
        self._canvas_subscriber = None
        self._background = DEFAULT_TURTLE_BACKGROUND

    def frames(self, session):
        return self.lacking(session, ("turtlesim", self.turtlesim), ("canvas", self.canvas))

    def _on_pose(self, pose, topic):
        name = topic.rsplit("/", 2)[-2]
        self.ros.count(topic)
        with self._lock:
            self._turtles[name] = {"name": name, "x": round(pose.x, 3), "y": round(pose.y, 3),
                                   "theta": round(pose.theta, 4)}
            self.turtlesim.set({"stamp_ms": int(time.time() * 1000), "background": list(self._background),
                                "turtles": sorted(self._turtles.values(), key=lambda turtle: turtle["name"]),
                                "size_m": TURTLE_WORLD_SIZE_M, "canvas": self._canvas_subscriber is not None})

    def _on_canvas(self, image):
        with self._lock:
            self.canvas.set({"png": base64.b64encode(bytes(image.data)).decode()})

    def on_graph(self, graph):
        """Subscribe to new turtles' poses and the canvas, drop those gone; read the background colour."""
        poses = {topic for topic, kind in graph.topic_types.items() if kind == TURTLE_POSE_TYPE}
        for topic in set(self._subscribers) - poses:
            self._subscribers.pop(topic).unregister()
            self.ros.counts(topic, False)
            with self._lock:
                self._turtles.pop(topic.rsplit("/", 2)[-2], None)
        for topic in poses - set(self._subscribers):
            self.ros.counts(topic)
            self._subscribers[topic] = rospy.Subscriber(topic, roslib.message.get_message_class(
                TURTLE_POSE_TYPE), self._on_pose, callback_args=topic, queue_size=1)
        canvases = sorted(topic for topic, kind in graph.topic_types.items()
                          if topic.endswith(CANVAS_SUFFIX) and kind == "sensor_msgs/CompressedImage")
        if canvases and self._canvas_subscriber is None:
            self._canvas_subscriber = rospy.Subscriber(canvases[0], CompressedImage, self._on_canvas, queue_size=1)
        elif not canvases and self._canvas_subscriber is not None:
            self._canvas_subscriber.unregister()
            self._canvas_subscriber = None
        node_of_publisher = {topic: nodes[0] for topic, nodes in graph.publishers if nodes}
        node = next((node_of_publisher[topic] for topic in sorted(poses) if topic in node_of_publisher), None)
        if node:
            try:
                background = tuple(int(rospy.get_param("{}/background_{}".format(node, channel))) for channel in "rgb")
            except (KeyError, ValueError, TypeError):
                background = DEFAULT_TURTLE_BACKGROUND
            with self._lock:
                self._background = background
