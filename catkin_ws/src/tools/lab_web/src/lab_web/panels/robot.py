"""The robot panel: the driven robot from <ns>/odom, its trail, and the newest LiDAR sweep from <ns>/scan in the
world (odom) frame, with the sim time (the odometry's stamp: the server does not follow /clock, see
lab_web.ros_context.RosContext.now) and the real-time factor (sim time over wall time between the odometry's
arrivals). The LiDAR's fixed offset from the robot's base comes from /tf_static and is composed with odom's pose,
which saves following /tf at 30 Hz and more."""
import threading
import time

import rospy
from nav_msgs.msg import Odometry
from sensor_msgs.msg import LaserScan
from tf2_msgs.msg import TFMessage

from lab_web import packed, scene
from lab_web.panels.base import Panel, Versioned
from lab_web.ros_context import now_s

RTF_WINDOW_S = 1.0


class RobotPanel(Panel):
    name = "robot"
    FRAMES = {
        "state": '{"stamp_ms": wall ms when the newest state arrived, "sim_time": s (the newest odometry\'s stamp) | '
                 'null (no /use_sim_time), "rtf": float | null, '
                 '"robot": {"x", "y", "yaw", "v", "w"} | null, "trail": {"reset": bool, "points": [[x, y], ...]} '
                 '(reset true: replace the page\'s trail with points; false: append them; a page keeps at most '
                 '3000 points), "scan": base64 of little-endian float32 x, y per world-frame LiDAR hit of the newest '
                 'sweep, only in the page\'s first state frame since that sweep came (the page keeps the last one)}  '
                 '<= 25 per second',
    }

    def __init__(self, ros):
        super().__init__(ros)
        self._lock = threading.Lock()
        self.state = Versioned()
        self.trail = scene.Trail()
        self._odom = None
        self.scan = Versioned("")   # packed.points_base64 of the newest sweep's hits, sent once per sweep: state
        #                             frames come at 25 a second, sweeps at 5 (2.9 kB of the 3.6 kB of a frame)
        self._clock_samples = []   # (wall s, sim s) of the odometry over the last RTF_WINDOW_S
        self._sim_rtf = (None, None)
        self._static_transforms = {}
        self._tf_static = rospy.Subscriber("/tf_static", TFMessage, self._on_tf_static, queue_size=10)
        self._subscribers = []
        self._subscribe()
        ros.follow_robot(self._on_robot_picked)

    def _subscribe(self):
        """Follow the robot in the context's namespace: its odom and scan (messages of other topics still on their
        way are dropped by the callbacks)."""
        with self._lock:
            self._odom_topic, self._scan_topic = self.ros.name("odom"), self.ros.name("scan")
        for topic in (self._odom_topic, self._scan_topic):
            self.ros.counts(topic)
        self._subscribers = [
            rospy.Subscriber(self._odom_topic, Odometry, self._on_odom, self._odom_topic, queue_size=1),
            rospy.Subscriber(self._scan_topic, LaserScan, self._on_scan, self._scan_topic, queue_size=1),
        ]

    def _on_robot_picked(self, _old_namespace):
        """Another robot: forget this one's pose, trail and sweep, and follow the new one's topics."""
        for subscriber in self._subscribers:
            subscriber.unregister()
        for topic in (self._odom_topic, self._scan_topic):
            self.ros.counts(topic, on=False)
        self._subscribe()
        with self._lock:
            self._odom = None
            self.scan.set("")
            self.trail.clear()
        self._publish_state()

    def frames(self, session):
        state = session.lacks("state", self.state)
        if state is None:
            return []
        with self._lock:
            reset, points, session.trail_cursor = self.trail.since(session.trail_cursor)
            scan = session.lacks("scan", self.scan)
        content = dict(state, trail={"reset": reset, "points": points})
        if scan is not None:
            content["scan"] = scan
        return [("state", content)]

    def robot_pose(self):
        """The robot's Pose2D in the odom frame, or None before its first odometry."""
        with self._lock:
            return self._odom[0] if self._odom else None

    def _on_odom(self, odom, topic):
        pose = odom.pose.pose
        robot = scene.Pose2D(pose.position.x, pose.position.y, scene.yaw_of(pose.orientation.z, pose.orientation.w))
        with self._lock:
            if topic != self._odom_topic:
                return   # the robot followed before a pick: its message was on its way
            self._odom = (robot, odom.twist.twist.linear.x, odom.twist.twist.angular.z, odom.child_frame_id)
            self.trail.add(robot.x, robot.y)
            self._sim_rtf = self._clock(odom.header.stamp)
        self.ros.stamped(odom.header.stamp)
        self.ros.count(self._odom_topic)
        self._publish_state()

    def _on_scan(self, scan, topic):
        self.ros.count(self._scan_topic)
        with self._lock:
            if self._odom is None or topic != self._scan_topic:
                return
            robot, _, _, base_frame = self._odom
            offset = scene.sensor_offset(self._static_transforms, base_frame, scan.header.frame_id)
        if offset is None:
            return   # /tf_static has not named the LiDAR's place on the robot yet
        points = packed.points_base64(scene.scan_points(scan.ranges, scan.angle_min, scan.angle_increment,
                                                        scan.range_min, scan.range_max, scene.compose(robot, offset)))
        with self._lock:
            if topic != self._scan_topic:
                return
            self.scan.set(points)
        self._publish_state()

    def _on_tf_static(self, message):
        with self._lock:
            for stamped in message.transforms:
                transform = stamped.transform
                self._static_transforms[stamped.child_frame_id] = (stamped.header.frame_id, scene.Pose2D(
                    transform.translation.x, transform.translation.y,
                    scene.yaw_of(transform.rotation.z, transform.rotation.w)))

    def _clock(self, stamp):
        """(sim time s of the odometry stamped `stamp`, or None without /use_sim_time; real-time factor over the last
        second of the odometry's arrivals, or None)."""
        if not self.ros.use_sim_time:
            return None, None
        sim = stamp.to_sec()
        wall = now_s()
        samples = self._clock_samples
        if samples and sim < samples[-1][1]:
            samples.clear()   # time went back (/gazebo/reset_simulation): measure afresh
        samples.append((wall, sim))
        while len(samples) > 2 and wall - samples[1][0] >= RTF_WINDOW_S:
            samples.pop(0)
        (wall0, sim0) = samples[0]
        rtf = (sim - sim0) / (wall - wall0) if wall - wall0 >= 0.2 else None
        return sim, rtf

    def _publish_state(self):
        with self._lock:
            sim, rtf = self._sim_rtf
            robot = scene.robot_state(*self._odom[:3]) if self._odom else None
            self.state.set({"stamp_ms": int(time.time() * 1000), "sim_time": sim, "rtf": rtf, "robot": robot})
