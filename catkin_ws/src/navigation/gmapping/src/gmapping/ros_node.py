"""slam_gmapping's ROS side: gmapping's graph over lab_nav.slam.

    rosrun gmapping slam_gmapping [scan:=/scan] [_base_frame:=base_footprint] ...

Subscribes `scan` (sensor_msgs/LaserScan, queue 5) and TF (odom_frame -> base_frame at each scan's stamp, waited
for up to TF_WAIT_S of sim time, as gmapping's TF message filter holds a scan until odometry reaches it; a scan
whose transform never comes is skipped with a throttled warning). Publishes `map` (nav_msgs/OccupancyGrid,
latched, frame map_frame, stamped now) and `map_metadata` (latched) with each map, `~entropy` (std_msgs/Float64,
latched, the matcher's pose entropy, only when > 0, as gmapping), and TF map_frame -> odom_frame on every tick of
transform_publish_period of sim time from start, stamped tick + tf_delay (gmapping.transform_ticks): identity until
the first scan is processed, then the SLAM's correction. Service `dynamic_map` (nav_msgs/GetMap): the last map;
before the first one the call fails, as gmapping's handler returns false. Parameters: lab_nav.slam.params; a bad
value stops the node with one line naming it. Survives a restarted master (master_reconnect) and the clock jumping
back (a simulator reset: the map is kept, TF's buffer is cleared by its listener, the next scan makes a map at once).
"""

import sys
import threading

import rospy
import tf2_ros
from nav_msgs.msg import MapMetaData, OccupancyGrid
from nav_msgs.srv import GetMap
from nav_ros.grids import NumpyGetMapResponse, grid_message
from nav_ros.sim_clock import SimTimeAlarm
from sensor_msgs.msg import LaserScan
from std_msgs.msg import Float64

from gmapping import messages
from gmapping.transform_ticks import TransformTicks
from lab_nav.slam import Slam, SlamError, params_from_dict
from master_reconnect import keep_registered
from sim_clock import quiet_time_notifications

NODE_NAME = "slam_gmapping"
TF_WAIT_S = 0.5
TF_CACHE_S = 30.0
PLANAR_TOLERANCE = 1e-3
WARN_PERIOD_S = 5.0


class SlamNode:
    """One slam_gmapping node running a lab_nav Slam with `params` (a SlamParams)."""

    def __init__(self, params):
        self.params = params
        self.slam = Slam(params)
        self._lock = threading.Lock()
        self._last_map = None
        self._laser = None  # (laser pose on the base, upside down) once the laser's mounting is known
        self._last_scan_stamp = None
        self._tf_buffer = tf2_ros.Buffer(cache_time=rospy.Duration(TF_CACHE_S))
        self._tf_listener = tf2_ros.TransformListener(self._tf_buffer)
        self._tf_broadcaster = tf2_ros.TransformBroadcaster()
        self._map_pub = rospy.Publisher("map", OccupancyGrid, latch=True, queue_size=1)
        self._metadata_pub = rospy.Publisher("map_metadata", MapMetaData, latch=True, queue_size=1)
        self._entropy_pub = rospy.Publisher("~entropy", Float64, latch=True, queue_size=1)
        self._service = rospy.Service("dynamic_map", GetMap, self._on_dynamic_map)
        self._scan_sub = rospy.Subscriber("scan", LaserScan, self._on_scan, queue_size=5)

    def spin_transform(self):
        """Send map -> odom on every tick of transform_publish_period of sim time until shutdown (0: never), the
        ticks a late wake-up slept past included (gmapping.transform_ticks). It sleeps on nav_ros.sim_clock's
        alarm, woken at each tick (20 a sim second by default) instead of at every /clock message as rospy.sleep."""
        period = self.params.transform_publish_period
        if period <= 0.0:
            rospy.spin()
            return
        ticks = TransformTicks(period)
        alarm = SimTimeAlarm()
        while not rospy.is_shutdown():
            now = rospy.get_time()
            if now > 0.0:  # 0: no /clock yet
                with self._lock:
                    correction = self.slam.correction
                for tick in ticks.due(now):
                    self._tf_broadcaster.sendTransform(messages.transform_message(
                        correction, self.params.map_frame, self.params.odom_frame,
                        rospy.Time.from_sec(tick + self.params.tf_delay)))
            try:
                alarm.sleep_until(ticks.next_s(now))
            except rospy.ROSTimeMovedBackwardsException:
                continue
            except rospy.ROSInterruptException:
                break

    def _on_scan(self, scan):
        if self._last_scan_stamp is not None and scan.header.stamp < self._last_scan_stamp:
            # The listener clears TF's buffer when the clock jumps back, but transforms stamped before the jump
            # can still arrive after it, and the buffer would then refuse all newer data as too old.
            self._tf_buffer.clear()
        self._last_scan_stamp = scan.header.stamp
        try:
            odom = self._tf_buffer.lookup_transform(self.params.odom_frame, self.params.base_frame,
                                                    scan.header.stamp, rospy.Duration(TF_WAIT_S))
            laser = self._laser or self._laser_mounting(scan.header.frame_id)
        except (tf2_ros.TransformException, rospy.ROSTimeMovedBackwardsException) as error:
            rospy.logwarn_throttle(WARN_PERIOD_S, f"slam_gmapping: scan at {scan.header.stamp.to_sec():.3f} "
                                                  f"skipped, no transform: {error}")
            return
        if laser is None:
            return
        laser_pose, upside_down = laser
        with self._lock:
            outcome = self.slam.add_scan(messages.scan_data(scan, upside_down),
                                         messages.pose_of(odom.transform), laser_pose)
            if outcome.map_due:
                self._publish_map()
        self._report(outcome)

    def _laser_mounting(self, laser_frame):
        """The laser's pose on the base and whether it is upside down; None (with a warning) if it is not level."""
        mount = self._tf_buffer.lookup_transform(self.params.base_frame, laser_frame, rospy.Time(0),
                                                 rospy.Duration(TF_WAIT_S)).transform
        z_axis = messages.laser_z_axis(mount.rotation)
        if abs(abs(z_axis) - 1.0) > PLANAR_TOLERANCE:
            rospy.logwarn_throttle(WARN_PERIOD_S, "Laser has to be mounted planar! Z-coordinate has to be 1 or -1, "
                                                  f"but gave: {z_axis:.5f}")
            return None
        upside_down = z_axis < 0.0
        rospy.loginfo("Laser is mounted upside down." if upside_down else "Laser is mounted upwards.")
        self._laser = (messages.pose_of(mount), upside_down)
        rospy.loginfo("Initialization complete")
        return self._laser

    def _publish_map(self):
        values, geometry = self.slam.occupancy()
        grid = grid_message(geometry, values, self.params.map_frame, rospy.Time.now())
        self._map_pub.publish(grid)
        self._metadata_pub.publish(grid.info)
        if self.slam.entropy > 0.0:
            self._entropy_pub.publish(Float64(self.slam.entropy))
        self._last_map = grid

    def _report(self, outcome):
        if outcome.clock_jumped_back:
            rospy.logwarn("slam_gmapping: the clock jumped back (simulation reset?): keeping the map, "
                          "restarting the update timing")
        if outcome.odometry_jumped:
            rospy.logwarn("slam_gmapping: the odometry jumped (a teleport or a reset?): the scans across the jump "
                          "are left out")
        if not outcome.processed:
            return
        if outcome.match is None:
            rospy.loginfo("Registering First Scan")
        elif not outcome.matched:
            rospy.loginfo(f"Scan Matching Failed, using odometry. Likelihood={outcome.match.score:.1f}")

    def _on_dynamic_map(self, _request):
        with self._lock:
            grid = self._last_map
        if grid is None:
            raise rospy.ServiceException("slam_gmapping has no map yet (it makes one from the first scan)")
        return NumpyGetMapResponse(map=grid)


def main():
    """Entry point of `rosrun gmapping slam_gmapping`; exits 1 with a one-line reason on bad parameters."""
    quiet_time_notifications()
    rospy.init_node(NODE_NAME)
    try:
        params = params_from_dict(rospy.get_param("~", {}))
    except SlamError as error:
        rospy.logfatal(f"slam_gmapping: {error}")
        return 1
    node = SlamNode(params)
    keep_registered()
    try:
        node.spin_transform()
    except rospy.ROSInterruptException:
        pass
    return 0


if __name__ == "__main__":
    sys.exit(main())
