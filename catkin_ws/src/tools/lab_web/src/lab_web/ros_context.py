"""What the server panels share on the ROS side: names in the robot's namespace, the publish-rate meter, the set
of topics a panel already counts, cached publishers, service calls that give up after a timeout, and the server's
time."""
import threading
import time
from typing import Dict, List, NamedTuple, Tuple

import rosgraph
import rospy

from lab_web.rates import TopicRates

SERVICE_WAIT_S = 2.0
"""A service that is not offered within this long is reported as not available."""
MODEL_CALL_TIMEOUT_S = 10.0
"""The simulator's /gazebo/* calls (spawn, move, delete, reset) answer at once: one that has not within this long
is abandoned and reported."""
DEFAULT_SERVICE_TIMEOUT_S = 120.0
"""The service form's calls (~service_timeout): longer than any course service takes on purpose (the Week 4
approach gives up after 60 s of sim time), short enough that a callback stuck for ever frees its worker."""
RESET_BACK_S = 1.0
"""A stamp this far behind the newest one is a reset of sim time (/gazebo/reset_simulation), not a late message."""


class BridgeError(Exception):
    """A request that could not be done; the text is shown on the page."""


def now_s():
    """Wall time for rates and throttles (the page and its user live in wall time)."""
    return time.monotonic()


class GraphState(NamedTuple):
    """The master's system state, read once per round for every panel."""

    publishers: List[Tuple[str, List[str]]]
    subscribers: List[Tuple[str, List[str]]]
    services: List[Tuple[str, List[str]]]
    topic_types: Dict[str, str]


def canonical_namespace(namespace):
    """A robot namespace as `RosContext.name` joins it: "" for the global one, else "/tb3_0" (no trailing /)."""
    return rosgraph.names.canonicalize_name("/" + namespace.strip("/")).rstrip("/") if namespace.strip("/") else ""


def own_or_global(namespace, relative, published):
    """The topic a display of the robot in `namespace` shows: the robot's own `<namespace>/<relative>` when something
    publishes it (a map or navigation stack per robot, as multi-robot SLAM launches them), else the global
    `/<relative>` a single stack uses."""
    own = "{}/{}".format(namespace, relative)
    return own if namespace and own in published else "/" + relative


class FollowedSubscribers:
    """Subscribers to a robot's own topics where it has them, else the global ones (own_or_global), re-made when
    the robot is picked or its topics appear or go (`on_graph`). `specs`: (relative name, message class, callback,
    Subscriber options); the callback gets the message and the name it came on. `on_switch(relative, name)` runs
    after a subscriber moved to another topic."""

    def __init__(self, ros, specs, on_switch=None):
        self._ros = ros
        self._specs = specs
        self._on_switch = on_switch
        self._lock = threading.Lock()
        self._published = set()
        self._subscribers = {}    # relative name -> (topic, rospy.Subscriber)
        self.update()
        ros.follow_robot(lambda _old: self.update())

    def name(self, relative):
        """The topic `relative` is followed on now."""
        with self._lock:
            return self._subscribers[relative][0]

    def on_graph(self, graph):
        with self._lock:
            self._published = {topic for topic, nodes in graph.publishers if nodes}
        self.update()

    def update(self):
        switched = []
        with self._lock:
            for relative, message_class, callback, options in self._specs:
                topic = own_or_global(self._ros.namespace, relative, self._published)
                old = self._subscribers.get(relative)
                if old is not None and old[0] == topic:
                    continue
                if old is not None:
                    old[1].unregister()
                    switched.append((relative, topic))
                self._subscribers[relative] = (topic, rospy.Subscriber(topic, message_class, callback, topic,
                                                                       **options))
        for relative, topic in switched:
            if self._on_switch is not None:
                self._on_switch(relative, topic)


class RosContext:
    """`robot_namespace`: the robot whose topics the panels show first ("": the global namespace; a page may pick
    another, `pick_robot`); `service_timeout_s`: how long a service form call may take before it is abandoned;
    `use_sim_time`: /use_sim_time as the node started (the server's time is then the newest stamp it received, see
    `now`)."""

    def __init__(self, robot_namespace="", service_timeout_s=DEFAULT_SERVICE_TIMEOUT_S, use_sim_time=False):
        self.service_timeout_s = service_timeout_s
        self.use_sim_time = use_sim_time
        self._newest_stamp = rospy.Time(0)
        self.namespace = canonical_namespace(robot_namespace)
        self.rates = TopicRates()
        self._lock = threading.Lock()
        self._counted = set()
        self._publishers = {}
        self._followers = []

    def name(self, relative):
        """`relative` in the robot's namespace."""
        return "{}/{}".format(self.namespace, relative)

    def follow_robot(self, callback):
        """`callback(old namespace)` runs after each change of the robot (its topics are then `name`'s)."""
        self._followers.append(callback)

    def pick_robot(self, namespace):
        """Show and drive the robot in `namespace` from now on (every page: the server follows one robot)."""
        namespace = canonical_namespace(namespace)
        with self._lock:
            old, self.namespace = self.namespace, namespace
        if old != namespace:
            for callback in self._followers:
                callback(old)

    def stamped(self, stamp):
        """A message stamped `stamp` came from the robot (its odometry: 30 Hz of sim time from tb3_sim or Gazebo)."""
        with self._lock:
            if stamp > self._newest_stamp or (self._newest_stamp - stamp).to_sec() > RESET_BACK_S:
                self._newest_stamp = stamp

    def now(self):
        """The stamp of what the server publishes (the tools' poses), as RViz's ros::Time::now(): sim time under
        /use_sim_time, else wall time. The node does not follow /clock (rospy.init_node's disable_rostime): rospy's
        own /clock subscriber (and the graph panel's rate count, lab_web.panels.graph.UNMEASURED_TOPICS) took 100
        messages a second at real time, the largest single cost of the server's CPU with navigation shown (2.2 % of
        a core of 11.6 %). Its sim time is the newest odometry's stamp instead, at
        most one odometry period (33 ms) behind /clock, and 0 before any odometry, as rospy's before /clock."""
        if not self.use_sim_time:
            return rospy.Time.now()   # wall time: rospy without /clock
        with self._lock:
            return self._newest_stamp

    def count(self, topic):
        """A message arrived on `topic`, which a panel subscribes to anyway (the graph panel's rate)."""
        self.rates.count(topic, now_s())

    def counts(self, topic, on=True):
        """A panel counts `topic`'s messages itself (on) or no longer (off): the graph panel need not."""
        with self._lock:
            (self._counted.add if on else self._counted.discard)(topic)

    def counted(self):
        with self._lock:
            return set(self._counted)

    def publisher(self, topic, message_class, latch=False):
        """One publisher per topic for the whole server."""
        with self._lock:
            publisher = self._publishers.get(topic)
            if publisher is None:
                publisher = self._publishers[topic] = rospy.Publisher(topic, message_class, queue_size=1, latch=latch)
            return publisher

    @staticmethod
    def call(name, service_class, *args, timeout_s=MODEL_CALL_TIMEOUT_S):
        """The reply of `name`, or BridgeError naming the service: not offered, failed, or no answer within
        `timeout_s`. rospy's calls have no timeout, so the call's connection is shut when it expires, which ends
        the wait in this thread (the service's own callback runs on; its late reply goes nowhere)."""
        try:
            rospy.wait_for_service(name, SERVICE_WAIT_S)
        except rospy.ROSException:
            raise BridgeError("{} is not available: is the simulator (or the node offering it) running?"
                              .format(name)) from None
        proxy = rospy.ServiceProxy(name, service_class, persistent=True)   # persistent: close() reaches the socket
        expired = threading.Event()

        def expire():
            expired.set()
            proxy.close()
        timer = threading.Timer(timeout_s, expire)
        timer.daemon = True
        timer.start()
        try:
            return proxy(*args)
        except Exception as error:   # noqa: BLE001 - whatever the shut connection raised, the cause is the timeout
            if expired.is_set():
                raise BridgeError("{} did not answer within {:g} s: its node may be stuck in its callback (the call "
                                  "was abandoned)".format(name, timeout_s)) from None
            if isinstance(error, (rospy.ServiceException, rospy.ROSSerializationException)):
                raise BridgeError("{} failed: {}".format(name, error)) from None
            raise
        finally:
            timer.cancel()
            proxy.close()
