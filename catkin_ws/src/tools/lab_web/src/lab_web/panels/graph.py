"""The graph panel: the master's nodes, topics (with publish rates) and services every GRAPH_PERIOD_S, and the
echo of the topic a page selects.

Rates are measured like `rostopic hz` but only on topics someone else already subscribes to, or the selected one,
so opening the page never makes a lazy sensor (camera, model states) start working; /clock only while selected."""
import threading

import rosgraph
import roslib.message
import rospy

from lab_web import commands
from lab_web.message_text import message_text
from lab_web.panels.base import Panel, Versioned
from lab_web.ros_context import BridgeError, now_s

ECHO_PERIOD_S = 0.2
HEAVY_TYPES = ("sensor_msgs/Image", "sensor_msgs/CompressedImage", "sensor_msgs/PointCloud2")
"""Never subscribed just to measure a rate: megabytes per message."""
UNMEASURED_TOPICS = ("/clock",)
"""Never subscribed just to measure a rate either: every node on /use_sim_time subscribes to /clock, so it would
always be measured, at 100 messages a second at real time (the largest single cost of the server's CPU with
navigation shown, 2.2 % of a core; the top bar shows the real-time factor). Its rate shows while it is echoed."""


class GraphPanel(Panel):
    name = "graph"
    FRAMES = {
        "graph": '{"nodes": [name], "topics": [{"name", "type", "hz": float | null, "publishers": [node], '
                 '"subscribers": [node]}], "services": [{"name", "node"}]}  every 2 s, when it changed',
        "echo": '{"topic", "text": the latest message as YAML-like text}  <= 5 Hz, while selected',
    }
    COMMANDS = {"echo": commands.CommandSpec((("topic", commands.name_or_null),),
                                             "select the topic to echo (null: none)")}

    def __init__(self, ros):
        super().__init__(ros)
        self._lock = threading.Lock()
        self.graph = Versioned()
        self._rate_subscribers = {}
        self._echo = {}            # topic -> [subscriber, Versioned text, last text time, owners]

    def frames(self, session):
        out = self.lacking(session, ("graph", self.graph))
        echo = self._echo_of(session.owner)
        if echo is not None and session.sent.get("echo") != (echo[0], echo[1].version):
            session.sent["echo"] = (echo[0], echo[1].version)
            out.append(("echo", {"topic": echo[0], "text": echo[1].value}))
        return out

    def on_graph(self, graph):
        self._measure_rates(graph.topic_types, dict(graph.subscribers))
        now = now_s()
        me = rospy.get_name()
        subscribed = dict(graph.subscribers)
        topics = [{"name": topic, "type": graph.topic_types.get(topic, "?"), "hz": self.ros.rates.rate_hz(topic, now),
                   "publishers": sorted(node for node in nodes if node != me),
                   "subscribers": sorted(node for node in subscribed.get(topic, []) if node != me)}
                  for topic, nodes in sorted(graph.publishers)]
        nodes = sorted({node for _, names in graph.publishers + graph.subscribers + graph.services
                        for node in names} - {me})
        content = {"nodes": nodes, "topics": topics,
                   "services": [{"name": name, "node": names[0]} for name, names in sorted(graph.services)
                                if me not in names]}
        with self._lock:
            if content != self.graph.value:
                self.graph.set(content)

    def _measure_rates(self, topic_types, subscribers):
        """Count messages of light topics that another node subscribes to (AnyMsg: no deserialising)."""
        me = rospy.get_name()
        counted = self.ros.counted()
        watched = {topic for topic, kind in topic_types.items()
                   if kind not in HEAVY_TYPES and topic not in UNMEASURED_TOPICS and topic not in counted
                   and any(node != me for node in subscribers.get(topic, []))}
        for topic in set(self._rate_subscribers) - watched:
            self._rate_subscribers.pop(topic).unregister()
            self.ros.rates.forget(topic)
        for topic in watched - set(self._rate_subscribers):
            self._rate_subscribers[topic] = rospy.Subscriber(
                topic, rospy.AnyMsg, lambda _, name=topic: self.ros.count(name), queue_size=1)

    # --- echo ------------------------------------------------------------------------------------------

    def handle(self, session, kind, args):
        session.sent.pop("echo", None)
        self.select_echo(session.owner, args["topic"])

    def select_echo(self, owner, topic):
        """Page `owner` echoes `topic` from now on (None: nothing). Unknown topics are refused."""
        with self._lock:
            for name, entry in list(self._echo.items()):
                entry[3].discard(owner)
                if not entry[3]:
                    entry[0].unregister()
                    del self._echo[name]
        if topic is None:
            return
        topic = rosgraph.names.canonicalize_name(topic if topic.startswith("/") else "/" + topic)
        kind = dict(rosgraph.Master(rospy.get_name()).getTopicTypes()).get(topic)
        message_class = roslib.message.get_message_class(kind) if kind else None
        if message_class is None:
            raise BridgeError("no topic {} is published (or its type is unknown here)".format(topic))
        with self._lock:
            if topic not in self._echo:
                text = Versioned("(waiting for the first message on {})".format(topic))
                subscriber = rospy.Subscriber(topic, message_class, self._on_echo, callback_args=topic, queue_size=1)
                self._echo[topic] = [subscriber, text, 0.0, set()]
            self._echo[topic][3].add(owner)

    def _on_echo(self, message, topic):
        now = now_s()
        if topic not in self.ros.counted() and topic not in self._rate_subscribers:
            self.ros.count(topic)
        with self._lock:
            entry = self._echo.get(topic)
            if entry is None or now - entry[2] < ECHO_PERIOD_S:
                return
            entry[2] = now
        text = message_text(message)
        with self._lock:
            entry[1].set(text)

    def _echo_of(self, owner):
        """(topic, Versioned text) that page `owner` echoes, or None."""
        with self._lock:
            for topic, entry in self._echo.items():
                if owner in entry[3]:
                    return topic, entry[1]
        return None

    def disconnect(self, owner):
        self.select_echo(owner, None)
