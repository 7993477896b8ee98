"""amcl (imports rospy): the particle filter of lab_nav.localization on /scan, odometry TF and the map.

Node `amcl`. The map comes from the `static_map` service (asked every 0.5 s until map_server answers; the node does
nothing else until then) or, with ~use_map_topic, from `map`. Each scan: the odometry pose (odom -> base frame) at
the scan's stamp is looked up (scans whose TF is not there yet are dropped); after update_min_d or update_min_a of
motion (or once after start, a new initial pose, global localisation or request_nomotion_update) the filter moves,
weights and resamples, `amcl_pose` (latched, frame map, stamp = the scan's) and `particlecloud` (latched, all
particles, written from the filter's array only for a subscriber: nav_ros.particle_cloud) are published; on
every scan TF map -> odom is sent, stamped scan stamp + transform_tolerance.
`initialpose` in frame map (or an empty frame, with a warning) re-initialises the particles; other frames are
ignored with a warning. The last pose is written back to ~initial_pose_x/y/a and ~initial_cov_xx/yy/aa every 1 /
save_pose_rate s.
"""
import math
import threading

import numpy as np
import rospy
import tf2_ros
from geometry_msgs.msg import PoseArray, PoseWithCovarianceStamped
from nav_msgs.msg import OccupancyGrid
from nav_msgs.srv import SetMap, SetMapResponse
from nav_ros import grids, poses
from nav_ros.params import ParamError
from nav_ros.particle_cloud import ParticleCloud
from nav_ros.sim_clock import PeriodicThread
from sensor_msgs.msg import LaserScan
from std_srvs.srv import Empty, EmptyResponse

from lab_nav.localization.particle_filter import ParticleFilter
from lab_nav.planning.periodic import PeriodicTasks
from sim_clock import quiet_time_notifications
from stop_request.closed_topic import publish_unless_shut_down

from .config import read_config

NODE_NAME = "amcl"
TF_WAIT_S = 0.1
NO_SCAN_WARN_S = 15.0


def covariance_message(covariance):
    """The 36-value row-major 6x6 covariance amcl publishes: x/y block and yaw variance."""
    out = [0.0] * 36
    out[0], out[1], out[6], out[7] = covariance[0, 0], covariance[0, 1], covariance[1, 0], covariance[1, 1]
    out[35] = covariance[2, 2]
    return out


class AmclNode:
    def __init__(self, config):
        self.config = config
        self._lock = threading.Lock()
        self._filter = None
        self._map_to_odom = None
        self._last_scan_time = None
        self._last_saved = None
        self._last_estimate = None
        self._started = rospy.get_time()
        self._tf = tf2_ros.Buffer()
        self._tf_listener = tf2_ros.TransformListener(self._tf)
        self._tf_out = tf2_ros.TransformBroadcaster()
        self._laser_poses = {}
        self._pose_pub = rospy.Publisher("amcl_pose", PoseWithCovarianceStamped, queue_size=2, latch=True)
        self._cloud_pub = rospy.Publisher("particlecloud", PoseArray, queue_size=2, latch=True)

    # --- the map ------------------------------------------------------------------------------------------
    def set_map(self, grid):
        """A new map: a new filter around the configured initial pose."""
        geometry, cells = grids.cells_of(grid)
        rospy.loginfo("Received a %d X %d map @ %.3f m/pix", geometry.width, geometry.height, geometry.resolution)
        pf = ParticleFilter.for_map(geometry, cells, self.config.filter, self.config.seed)
        x, y, a = self.config.initial_pose
        xx, yy, aa = self.config.initial_cov
        pf.init_gaussian((x, y, a), np.diag([xx, yy, aa]))
        with self._lock:
            self._filter = pf

    def start(self):
        if self.config.use_map_topic:
            rospy.Subscriber("map", OccupancyGrid, self._on_map_topic, queue_size=1)
        else:
            grid = grids.request_static_map()
            if grid is None:
                return
            self.set_map(grid)
        rospy.Subscriber("scan", LaserScan, self._on_scan, queue_size=1)
        rospy.Subscriber("initialpose", PoseWithCovarianceStamped, self._on_initial_pose, queue_size=2)
        rospy.Service("global_localization", Empty, self._on_global_localization)
        rospy.Service("request_nomotion_update", Empty, self._on_nomotion_update)
        rospy.Service("set_map", SetMap, self._on_set_map)
        checks = PeriodicTasks()
        checks.add(NO_SCAN_WARN_S, self._check_scans, first_after_period=True)
        PeriodicThread(checks, "amcl_scan_check")

    def _on_map_topic(self, grid):
        if self.config.first_map_only and self._filter is not None:
            return
        try:
            self.set_map(grid)
        except ValueError as error:
            rospy.logerr("Ignoring a map that cannot be used: %s", error)

    def _on_set_map(self, request):
        try:
            self.set_map(request.map)
        except ValueError as error:
            rospy.logerr("set_map: %s", error)
            return SetMapResponse(False)
        self._reinitialise(request.initial_pose)
        return SetMapResponse(True)

    # --- pose requests ------------------------------------------------------------------------------------
    def _on_initial_pose(self, message):
        frame = message.header.frame_id.lstrip("/")
        if frame == "":
            rospy.logwarn("Received initial pose with empty frame_id.  You should always supply a frame_id.")
        elif frame != self.config.global_frame_id:
            rospy.logwarn("Ignoring initial pose in frame \"%s\"; initial poses must be in the global frame, "
                          "\"%s\"", frame, self.config.global_frame_id)
            return
        self._reinitialise(message)

    def _reinitialise(self, message):
        pose = poses.from_pose(message.pose.pose)
        if not all(map(math.isfinite, pose)):
            rospy.logwarn("Ignoring an initial pose that is not finite: %s", pose)
            return
        c = message.pose.covariance
        cov = np.array([[c[0], c[1], 0.0], [c[6], c[7], 0.0], [0.0, 0.0, c[35]]])
        rospy.loginfo("Setting pose (%.6f): %.3f %.3f %.3f", rospy.get_time(), *pose)
        with self._lock:
            if self._filter is not None:
                self._filter.init_gaussian(pose, cov)

    def _on_global_localization(self, _request):
        rospy.loginfo("Initializing with uniform distribution")
        with self._lock:
            if self._filter is not None:
                self._filter.init_uniform()
        rospy.loginfo("Global initialisation done!")
        return EmptyResponse()

    def _on_nomotion_update(self, _request):
        with self._lock:
            if self._filter is not None:
                self._filter.request_update()
        rospy.loginfo("Requesting no-motion update")
        return EmptyResponse()

    # --- scans --------------------------------------------------------------------------------------------
    def _lookup(self, target, source, stamp):
        try:
            return poses.from_transform(self._tf.lookup_transform(target, source, stamp, rospy.Duration(TF_WAIT_S)))
        except (tf2_ros.LookupException, tf2_ros.ConnectivityException, tf2_ros.ExtrapolationException,
                tf2_ros.TimeoutException):
            return None

    def _laser_pose(self, frame):
        if frame not in self._laser_poses:
            pose = self._lookup(self.config.base_frame_id, frame, rospy.Time(0))
            if pose is None:
                return None
            self._laser_poses[frame] = pose
        return self._laser_poses[frame]

    def _on_scan(self, scan):
        self._last_scan_time = rospy.get_time()
        odom = self._lookup(self.config.odom_frame_id, self.config.base_frame_id, scan.header.stamp)
        laser = self._laser_pose(scan.header.frame_id)
        if odom is None or laser is None:
            return
        angles = scan.angle_min + scan.angle_increment * np.arange(len(scan.ranges))
        with self._lock:
            pf = self._filter
            if pf is None:
                return
            if pf.motion_due(odom):
                resampled = pf.update(odom, laser, np.asarray(scan.ranges, dtype=float), angles, scan.range_max)
                estimate = pf.estimate()
                self._map_to_odom = poses.compose(estimate.pose, poses.inverse(odom))
                publish_unless_shut_down(self._cloud_pub.publish, ParticleCloud(
                    pf.particles.copy(), self.config.global_frame_id, scan.header.stamp))
                if resampled or self._last_estimate is None:
                    self._publish_pose(estimate, scan.header.stamp)
            map_to_odom = self._map_to_odom
        if map_to_odom is not None and self.config.tf_broadcast:
            stamp = scan.header.stamp + rospy.Duration(self.config.transform_tolerance)
            publish_unless_shut_down(self._tf_out.sendTransform, poses.to_transform(
                map_to_odom, self.config.global_frame_id, self.config.odom_frame_id, stamp))
        self._save_pose()

    def _publish_pose(self, estimate, stamp):
        message = PoseWithCovarianceStamped()
        message.header.frame_id, message.header.stamp = self.config.global_frame_id, stamp
        message.pose.pose = poses.to_pose(estimate.pose)
        message.pose.covariance = covariance_message(estimate.covariance)
        self._last_estimate = estimate
        publish_unless_shut_down(self._pose_pub.publish, message)

    def _save_pose(self):
        rate = self.config.save_pose_rate
        estimate = self._last_estimate
        now = rospy.get_time()
        if rate <= 0 or estimate is None or (self._last_saved is not None and now - self._last_saved < 1.0 / rate):
            return
        self._last_saved = now
        for key, value in zip(("initial_pose_x", "initial_pose_y", "initial_pose_a"), estimate.pose):
            rospy.set_param("~" + key, float(value))
        for key, index in zip(("initial_cov_xx", "initial_cov_yy", "initial_cov_aa"), range(3)):
            rospy.set_param("~" + key, float(estimate.covariance[index, index]))

    def _check_scans(self):
        last = self._last_scan_time
        now = rospy.get_time()
        waited = now - last if last is not None else now - self._started
        if waited > NO_SCAN_WARN_S:
            rospy.logwarn("No laser scan received (and thus no pose updates have been published) for %f seconds."
                          "  Verify that data is being published on the %s topic.", waited, rospy.resolve_name("scan"))


def main():
    quiet_time_notifications()
    rospy.init_node(NODE_NAME)
    try:
        config = read_config(rospy.logwarn)
    except ParamError as error:
        rospy.logfatal(str(error))
        return 1
    node = AmclNode(config)
    node.start()
    rospy.spin()
    return 0
