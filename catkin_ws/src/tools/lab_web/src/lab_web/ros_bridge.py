"""The web view's ROS side (the only lab_web module that imports rospy): it watches the graph through the
interfaces any user has (topics, the master, services) and acts only through them, never inside a simulator.

Watched: <ns>/odom, <ns>/scan and /tf_static (the robot and its sweep: the LiDAR's fixed offset from the
robot's base composed with odom's pose, which saves following /tf at 30 Hz and more), /gazebo/world_markers
(walls and models), /gazebo/scene_primitives (the floor layer and static shapes as tb3_sim's drawing primitives,
passed to the page as they are), every turtlesim/Pose topic and turtlesim's ~canvas/compressed (turtles and pen
trails), the master's system state (the graph panel), the selected topic (echo) and <ns>/camera/rgb/image_raw while
a page shows it.
Rates are measured like `rostopic hz` but only on topics someone else already subscribes to, or the selected
one, so opening the page never makes a lazy sensor (camera, model states) start working.

Acted through: <ns>/cmd_vel and /turtle1/cmd_vel (teleop), /gazebo/spawn_sdf_model, get_model_state,
set_model_state, delete_model, reset_world, and any service with a plain request (the Week 4 form).
"""
import base64
import json
import threading
import time

import rosgraph
import roslib.message
import rospy
import rosservice
from gazebo_msgs.msg import ModelState
from gazebo_msgs.srv import DeleteModel, GetModelState, SetModelState, SpawnModel
from geometry_msgs.msg import Pose, Twist
from nav_msgs.msg import Odometry
from sensor_msgs.msg import CompressedImage, Image, LaserScan
from std_msgs.msg import String
from std_srvs.srv import Empty
from tf2_msgs.msg import TFMessage
from visualization_msgs.msg import MarkerArray

from lab_web import scene, service_form
from lab_web.message_text import message_text
from lab_web.rates import TopicRates
from lab_web.teleop import PUBLISH_RATE_HZ, TELEOP_LIMITS, TeleopGate
from lab_web.thumbnail import jpeg_thumbnail

GRAPH_PERIOD_S = 2.0
SERVICE_WAIT_S = 2.0
"""A service that is not offered within this long is reported as not available."""
MODEL_CALL_TIMEOUT_S = 10.0
"""The simulator's /gazebo/* calls (spawn, move, delete, reset) answer at once: one that has not within this long
is abandoned and reported."""
DEFAULT_SERVICE_TIMEOUT_S = 120.0
"""The service form's calls (~service_timeout): longer than any course service takes on purpose (the Week 4
approach gives up after 60 s of sim time), short enough that a callback stuck for ever frees its worker."""
CAMERA_PERIOD_S = 0.2
ECHO_PERIOD_S = 0.2
RTF_WINDOW_S = 1.0
HEAVY_TYPES = ("sensor_msgs/Image", "sensor_msgs/CompressedImage", "sensor_msgs/PointCloud2")
"""Never subscribed just to measure a rate: megabytes per message."""
TURTLE_POSE_TYPE = "turtlesim/Pose"
CANVAS_SUFFIX = "/canvas/compressed"
TURTLE_WORLD_SIZE_M = 500.0 / 45.0
"""turtlesim's 500 px canvas at 45 px per metre."""
DEFAULT_TURTLE_BACKGROUND = (69, 86, 255)
BOX_SIZE_M = 0.3
BOX_SDF = """<?xml version="1.0"?>
<sdf version="1.6"><model name="{name}"><pose>0 0 {half} 0 0 0</pose><link name="link">
<inertial><mass>1.0</mass></inertial>
<collision name="collision"><geometry><box><size>{size} {size} {size}</size></box></geometry></collision>
<visual name="visual"><geometry><box><size>{size} {size} {size}</size></box></geometry></visual>
</link></model></sdf>"""


class BridgeError(Exception):
    """A request that could not be done; the text is shown on the page."""


def _now():
    return time.monotonic()


class Versioned:
    """A value and a counter that goes up with each change, so each page sends only what is new to it."""

    def __init__(self, value=None):
        self.value, self.version = value, 0

    def set(self, value):
        self.value, self.version = value, self.version + 1


class RosBridge:
    """Create after rospy.init_node; `shutdown()` stops teleop (zero once) and the background threads.
    `service_timeout_s`: how long a service form call may take before it is abandoned."""

    def __init__(self, robot_namespace="", service_timeout_s=DEFAULT_SERVICE_TIMEOUT_S):
        self._service_timeout_s = service_timeout_s
        self._ns = rosgraph.names.canonicalize_name(robot_namespace).rstrip("/") if robot_namespace else ""
        self._lock = threading.Lock()
        self._stop = threading.Event()
        self.rates = TopicRates()
        self.teleop = TeleopGate()
        self.trail = scene.Trail()
        self.world = Versioned()
        self.state = Versioned()
        self.turtlesim = Versioned()
        self.canvas = Versioned()
        self.camera = Versioned()
        self.graph = Versioned()
        self._odom = None
        self._scan_points = []
        self._clock_samples = []
        self._turtles = {}
        self._turtle_subscribers = {}
        self._canvas_subscriber = None
        self._background = DEFAULT_TURTLE_BACKGROUND
        self._rate_subscribers = {}
        self._echo = {}            # topic -> [subscriber, Versioned text, last text time, owners]
        self._camera_owners = set()
        self._camera_subscriber = None
        self._camera_time = 0.0
        self._publishers = {}
        self._box_count = 0
        self._static_transforms = {}
        self._scene_primitives = None
        self._subscribers = [
            rospy.Subscriber(self._name("odom"), Odometry, self._on_odom, queue_size=1),
            rospy.Subscriber(self._name("scan"), LaserScan, self._on_scan, queue_size=1),
            rospy.Subscriber("/gazebo/world_markers", MarkerArray, self._on_world_markers, queue_size=1),
            rospy.Subscriber("/gazebo/scene_primitives", String, self._on_scene_primitives, queue_size=1),
            rospy.Subscriber("/tf_static", TFMessage, self._on_tf_static, queue_size=10),
        ]
        self._threads = [threading.Thread(target=loop, daemon=True, name=loop.__name__)
                         for loop in (self._teleop_loop, self._graph_loop)]
        for thread in self._threads:
            thread.start()

    teleop_limits = TELEOP_LIMITS

    def _name(self, relative):
        return "{}/{}".format(self._ns, relative)

    # --- what pages get --------------------------------------------------------------------------------

    def hello(self):
        return {"version": 1, "teleop_limits": {target: list(limits) for target, limits in TELEOP_LIMITS.items()},
                "world_frame": "odom"}

    def trail_since(self, cursor):
        """Trail.since under the lock (odometry callbacks add to the trail meanwhile)."""
        with self._lock:
            return self.trail.since(cursor)

    def _on_odom(self, odom):
        pose = odom.pose.pose
        robot = scene.Pose2D(pose.position.x, pose.position.y,
                             scene.yaw_of(pose.orientation.z, pose.orientation.w))
        with self._lock:
            self._odom = (robot, odom.twist.twist.linear.x, odom.twist.twist.angular.z, odom.child_frame_id)
            self.trail.add(robot.x, robot.y)
        self.rates.count(self._name("odom"), _now())
        self._publish_state()

    def _on_scan(self, scan):
        self.rates.count(self._name("scan"), _now())
        with self._lock:
            if self._odom is None:
                return
            robot, _, _, base_frame = self._odom
            offset = scene.sensor_offset(self._static_transforms, base_frame, scan.header.frame_id)
        if offset is None:
            return   # /tf_static has not named the LiDAR's place on the robot yet
        points = scene.scan_points(scan.ranges, scan.angle_min, scan.angle_increment, scan.range_min,
                                   scan.range_max, scene.compose(robot, offset))
        with self._lock:
            self._scan_points = points
        self._publish_state()

    def _on_tf_static(self, message):
        with self._lock:
            for stamped in message.transforms:
                transform = stamped.transform
                self._static_transforms[stamped.child_frame_id] = (stamped.header.frame_id, scene.Pose2D(
                    transform.translation.x, transform.translation.y,
                    scene.yaw_of(transform.rotation.z, transform.rotation.w)))

    def _on_world_markers(self, array):
        self.rates.count("/gazebo/world_markers", _now())
        markers = [scene.MarkerData(
            marker.ns, marker.type, marker.action,
            scene.Pose2D(marker.pose.position.x, marker.pose.position.y,
                         scene.yaw_of(marker.pose.orientation.z, marker.pose.orientation.w)),
            marker.scale.x, marker.scale.y, tuple((point.x, point.y) for point in marker.points), marker.text)
            for marker in array.markers]
        with self._lock:
            content = scene.with_scene(scene.world_content(markers), self._scene_primitives)
            if content != self.world.value:
                self.world.set(content)

    def _on_scene_primitives(self, message):
        primitives = scene.scene_primitives(message.data)
        with self._lock:
            self._scene_primitives = primitives
            if self.world.value is not None:
                self.world.set(scene.with_scene(self.world.value, primitives))

    def _sim_time_and_rtf(self):
        """(sim time s or None without /use_sim_time, real-time factor over the last second or None)."""
        sim = rospy.get_time()
        wall = _now()
        samples = self._clock_samples
        if samples and sim < samples[-1][1]:
            samples.clear()   # time went back (/gazebo/reset_simulation): measure afresh
        samples.append((wall, sim))
        while len(samples) > 2 and wall - samples[1][0] >= RTF_WINDOW_S:
            samples.pop(0)
        if rospy.rostime.is_wallclock():
            return None, None
        (wall0, sim0) = samples[0]
        rtf = (sim - sim0) / (wall - wall0) if wall - wall0 >= 0.2 else None
        return sim, rtf

    def _publish_state(self):
        with self._lock:
            sim, rtf = self._sim_time_and_rtf()
            robot = scene.robot_state(*self._odom[:3]) if self._odom else None
            self.state.set({"stamp_ms": int(time.time() * 1000), "sim_time": sim, "rtf": rtf, "robot": robot,
                            "scan": self._scan_points})

    # --- turtlesim -------------------------------------------------------------------------------------

    def _on_turtle_pose(self, pose, topic):
        name = topic.rsplit("/", 2)[-2]
        self.rates.count(topic, _now())
        with self._lock:
            self._turtles[name] = {"name": name, "x": round(pose.x, 3), "y": round(pose.y, 3),
                                   "theta": round(pose.theta, 4)}
            self.turtlesim.set({"stamp_ms": int(time.time() * 1000), "background": list(self._background),
                                "turtles": sorted(self._turtles.values(), key=lambda turtle: turtle["name"]),
                                "size_m": TURTLE_WORLD_SIZE_M, "canvas": self._canvas_subscriber is not None})

    def _on_canvas(self, image):
        with self._lock:
            self.canvas.set(base64.b64encode(bytes(image.data)).decode())

    def _follow_turtlesim(self, topic_types, node_of_publisher):
        """Subscribe to new turtles' poses and the canvas, drop those gone; read the background colour."""
        poses = {topic for topic, kind in topic_types.items() if kind == TURTLE_POSE_TYPE}
        for topic in set(self._turtle_subscribers) - poses:
            self._turtle_subscribers.pop(topic).unregister()
            with self._lock:
                self._turtles.pop(topic.rsplit("/", 2)[-2], None)
        for topic in poses - set(self._turtle_subscribers):
            self._turtle_subscribers[topic] = rospy.Subscriber(topic, roslib.message.get_message_class(
                TURTLE_POSE_TYPE), self._on_turtle_pose, callback_args=topic, queue_size=1)
        canvases = sorted(topic for topic, kind in topic_types.items()
                          if topic.endswith(CANVAS_SUFFIX) and kind == "sensor_msgs/CompressedImage")
        if canvases and self._canvas_subscriber is None:
            self._canvas_subscriber = rospy.Subscriber(canvases[0], CompressedImage, self._on_canvas, queue_size=1)
        elif not canvases and self._canvas_subscriber is not None:
            self._canvas_subscriber.unregister()
            self._canvas_subscriber = None
        turtlesim_node = next((node_of_publisher[topic] for topic in sorted(poses) if topic in node_of_publisher), None)
        if turtlesim_node:
            try:
                background = tuple(int(rospy.get_param("{}/background_{}".format(turtlesim_node, channel)))
                                   for channel in "rgb")
            except (KeyError, ValueError, TypeError):
                background = DEFAULT_TURTLE_BACKGROUND
            with self._lock:
                self._background = background

    # --- the graph panel -------------------------------------------------------------------------------

    def _graph_loop(self):
        master = rosgraph.Master(rospy.get_name())
        while not self._stop.wait(0 if self.graph.version == 0 else GRAPH_PERIOD_S):
            try:
                publishers, subscribers, services = master.getSystemState()
                topic_types = dict(master.getTopicTypes())
            except (OSError, rosgraph.MasterException):
                continue   # the master is restarting: the next round will see it
            node_of_publisher = {topic: nodes[0] for topic, nodes in publishers if nodes}
            self._follow_turtlesim(topic_types, node_of_publisher)
            self._measure_rates(topic_types, dict(subscribers))
            now = _now()
            me = rospy.get_name()
            subscribed = dict(subscribers)
            topics = [{"name": topic, "type": topic_types.get(topic, "?"), "hz": self.rates.rate_hz(topic, now),
                       "publishers": sorted(node for node in nodes if node != me),
                       "subscribers": sorted(node for node in subscribed.get(topic, []) if node != me)}
                      for topic, nodes in sorted(publishers)]
            nodes = sorted({node for _, names in publishers + subscribers + services for node in names} - {me})
            graph = {"nodes": nodes, "topics": topics,
                     "services": [{"name": name, "node": names[0]} for name, names in sorted(services)
                                  if me not in names]}
            with self._lock:
                if graph != self.graph.value:
                    self.graph.set(graph)

    def _measure_rates(self, topic_types, subscribers):
        """Count messages of light topics that another node subscribes to (AnyMsg: no deserialising)."""
        me = rospy.get_name()
        watched = {topic for topic, kind in topic_types.items()
                   if kind not in HEAVY_TYPES and any(node != me for node in subscribers.get(topic, []))}
        watched = {topic for topic in watched
                   if topic not in (self._name("odom"), self._name("scan"), "/gazebo/world_markers")
                   and topic not in self._turtle_subscribers}
        for topic in set(self._rate_subscribers) - watched:
            self._rate_subscribers.pop(topic).unregister()
            self.rates.forget(topic)
        for topic in watched - set(self._rate_subscribers):
            self._rate_subscribers[topic] = rospy.Subscriber(
                topic, rospy.AnyMsg, lambda _, name=topic: self.rates.count(name, _now()), queue_size=1)

    # --- echo and camera -------------------------------------------------------------------------------

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

    def _counted_elsewhere(self, topic):
        """True when another subscription of the bridge already counts `topic`'s messages."""
        return (topic in (self._name("odom"), self._name("scan"), "/gazebo/world_markers")
                or topic in self._rate_subscribers or topic in self._turtle_subscribers)

    def _on_echo(self, message, topic):
        now = _now()
        if not self._counted_elsewhere(topic):
            self.rates.count(topic, now)
        with self._lock:
            entry = self._echo.get(topic)
            if entry is None or now - entry[2] < ECHO_PERIOD_S:
                return
            entry[2] = now
        text = message_text(message)
        with self._lock:
            entry[1].set(text)

    def echo_of(self, owner):
        """(topic, Versioned text) that page `owner` echoes, or None."""
        with self._lock:
            for topic, entry in self._echo.items():
                if owner in entry[3]:
                    return topic, entry[1]
        return None

    def set_camera(self, owner, on):
        with self._lock:
            (self._camera_owners.add if on else self._camera_owners.discard)(owner)
            wanted = bool(self._camera_owners)
            if wanted and self._camera_subscriber is None:
                self._camera_subscriber = rospy.Subscriber(self._name("camera/rgb/image_raw"), Image,
                                                           self._on_camera, queue_size=1, buff_size=2 ** 24)
            elif not wanted and self._camera_subscriber is not None:
                self._camera_subscriber.unregister()
                self._camera_subscriber = None

    def _on_camera(self, image):
        now = _now()
        if now - self._camera_time < CAMERA_PERIOD_S:
            return
        self._camera_time = now
        thumbnail = jpeg_thumbnail(image.data, image.width, image.height, image.encoding, image.step)
        if thumbnail is not None:
            with self._lock:
                self.camera.set(thumbnail)

    def disconnect(self, owner):
        """Page `owner` went away: stop what it drove, drop its echo and camera."""
        self.teleop.disconnect(owner, _now())
        self.set_camera(owner, False)
        self.select_echo(owner, None)
        self._publish_teleop()

    # --- teleop ----------------------------------------------------------------------------------------

    def command(self, owner, target, linear, angular):
        self.teleop.command(owner, target, linear, angular, _now())
        if linear == 0.0 and angular == 0.0:
            self._publish_teleop()   # a released key stops the robot now, not at the next tick

    def _teleop_loop(self):
        while not self._stop.wait(1.0 / PUBLISH_RATE_HZ):
            self._publish_teleop()

    def _publish_teleop(self):
        for target, linear, angular in self.teleop.tick(_now()):
            topic = self._name("cmd_vel") if target == "robot" else "/turtle1/cmd_vel"
            with self._lock:
                publisher = self._publishers.get(topic)
                if publisher is None:
                    publisher = self._publishers[topic] = rospy.Publisher(topic, Twist, queue_size=1)
            twist = Twist()
            twist.linear.x, twist.angular.z = linear, angular
            try:
                publisher.publish(twist)
            except rospy.ROSException:
                return   # shutting down

    # --- requests (blocking: the server runs them in worker threads) ----------------------------------

    def _call(self, name, service_class, *args, timeout_s=MODEL_CALL_TIMEOUT_S):
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
        reply = self._call("/gazebo/spawn_sdf_model", SpawnModel, name,
                           BOX_SDF.format(name=name, size=BOX_SIZE_M, half=BOX_SIZE_M / 2), "", pose, "world")
        if not reply.success:
            raise BridgeError(reply.status_message)
        return "spawned {} at ({:.2f}, {:.2f})".format(name, x, y)

    def move_model(self, name, x, y):
        current = self._call("/gazebo/get_model_state", GetModelState, name, "")
        if not current.success:
            raise BridgeError(current.status_message)
        state = ModelState(model_name=name, pose=current.pose, reference_frame="world")
        state.pose.position.x, state.pose.position.y = x, y
        reply = self._call("/gazebo/set_model_state", SetModelState, state)
        if not reply.success:
            raise BridgeError(reply.status_message)
        return "moved {} to ({:.2f}, {:.2f})".format(name, x, y)

    def delete_model(self, name):
        reply = self._call("/gazebo/delete_model", DeleteModel, name)
        if not reply.success:
            raise BridgeError(reply.status_message)
        return "deleted {}".format(name)

    def reset_world(self):
        self._call("/gazebo/reset_world", Empty)
        return "world reset"

    def _request_class(self, service):
        try:
            service_class = rosservice.get_service_class_by_name(service)
        except (rosservice.ROSServiceException, rosservice.ROSServiceIOException, OSError) as error:
            raise BridgeError("{}: {}".format(service, str(error) or "not available")) from None
        return service_class

    def service_fields(self, service):
        try:
            return json.dumps(service_form.request_fields(self._request_class(service)._request_class))
        except service_form.FormError as error:
            raise BridgeError(str(error)) from None

    def call_service(self, service, values):
        service_class = self._request_class(service)
        try:
            request = service_class._request_class(**service_form.request_values(service_class._request_class, values))
        except service_form.FormError as error:
            raise BridgeError(str(error)) from None
        return service_form.response_text(self._call(service, service_class, request,
                                                     timeout_s=self._service_timeout_s))

    def shutdown(self):
        """Zero every target a page was driving, then stop the threads."""
        self.teleop.stop_all(_now())
        self._publish_teleop()
        self._stop.set()
