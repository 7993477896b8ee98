"""One costmap of move_base (imports rospy): its layers fed from /map and the laser, and its topics.

Topics under ~<name>/ (e.g. /move_base/global_costmap/):
- `costmap` (nav_msgs/OccupancyGrid, not latched): each new subscriber gets the full grid at once; after that a
  full grid goes out only when the size, resolution or origin changes (every shift of the rolling local
  costmap, a resized map for the global one).
- `costmap_updates` (map_msgs/OccupancyGridUpdate): otherwise, at publish_frequency and only while someone
  subscribes to `costmap`, the bounding box of the cells that changed.
- `footprint` (geometry_msgs/PolygonStamped): the padded footprint at the robot's pose, in the global frame, on
  every update (built only while someone subscribes).
Values are translated 0 -> 0, 1-252 -> 1-98, 253 -> 99, 254 -> 100, 255 -> -1.

The static layer (global costmap) subscribes to `map` and resizes the costmap to each map's geometry. Laser
scans are projected into the global frame at their stamp (dropped when TF is not available within
transform_tolerance); +inf readings neither mark nor clear, readings at range_max clear only. The robot pose
is TF global_frame -> robot_base_frame. An update recomputes only the cells its scans changed (lab_nav's
LayeredCostmap), so scans that see what the map already has cost a comparison of their window.
"""
import threading

import numpy as np
import rospy
import tf2_ros
from geometry_msgs.msg import Point32, PolygonStamped
from map_msgs.msg import OccupancyGridUpdate
from nav_msgs.msg import OccupancyGrid
from nav_ros import grids, poses
from nav_ros.subscribe import SendOnSubscribe
from sensor_msgs.msg import LaserScan

from lab_nav.costmap.layered import LayeredCostmap, changed_box
from lab_nav.costmap.values import to_occupancy
from lab_nav.maps.geometry import MapGeometry
from stop_request.closed_topic import publish_unless_shut_down

TF_TIMEOUT_S = 0.2


class CostmapRos:
    def __init__(self, config, tf_buffer):
        self.config = config
        self.name = config.name
        self._tf = tf_buffer
        self.lock = threading.RLock()
        self._scans = []
        self._published = None
        self._pose = None
        self._dirty = True
        p = config.params
        if config.static_map:
            geometry = MapGeometry(config.resolution, 1, 1, 0.0, 0.0)
        else:
            geometry = MapGeometry(config.resolution, int(round(config.width / config.resolution)),
                                   int(round(config.height / config.resolution)), 0.0, 0.0)
        self.costmap = LayeredCostmap(geometry, p, static=config.static_map)
        self._map_received = threading.Event()
        ns = f"~{self.name}/"
        self._grid_pub = rospy.Publisher(ns + "costmap", OccupancyGrid, queue_size=1,
                                         subscriber_listener=SendOnSubscribe(self.grid_message))
        self._update_pub = rospy.Publisher(ns + "costmap_updates", OccupancyGridUpdate, queue_size=1)
        self._footprint_pub = rospy.Publisher(ns + "footprint", PolygonStamped, queue_size=1)

    # --- start-up -----------------------------------------------------------------------------------------
    def start(self):
        """Wait for TF robot -> global frame, then (static layer) for the first map; start the layers' inputs
        and make the first update. False when ROS shut down while waiting."""
        c = self.config
        while not rospy.is_shutdown():
            try:
                self._tf.lookup_transform(c.global_frame, c.robot_base_frame, rospy.Time(0), rospy.Duration(5.0))
                break
            except (tf2_ros.LookupException, tf2_ros.ConnectivityException, tf2_ros.ExtrapolationException,
                    tf2_ros.TimeoutException) as error:
                rospy.logwarn("Timed out waiting for transform from %s to %s to become available before running "
                              "costmap, tf error: %s", c.robot_base_frame, c.global_frame, error)
        if c.static_map:
            rospy.loginfo("Requesting the map...")
            rospy.Subscriber("map", OccupancyGrid, self._on_map, queue_size=1)
            while not self._map_received.wait(0.1):
                if rospy.is_shutdown():
                    return False
        for source in c.sources:
            rospy.Subscriber(source.topic, LaserScan, self._on_scan, callback_args=source, queue_size=1)
            rospy.loginfo("    Subscribed to Topics: %s", source.topic)
        self.update()
        return not rospy.is_shutdown()

    def schedule(self, tasks):
        """Add the update (update_frequency) and publishing (publish_frequency; none at 0) to `tasks`, a
        lab_nav PeriodicTasks that move_base runs in sim time from one thread."""
        c = self.config
        if c.update_frequency > 0:
            tasks.add(1.0 / c.update_frequency, self.update)
        if c.publish_frequency > 0:
            tasks.add(1.0 / c.publish_frequency, self.publish)

    def _on_map(self, grid):
        try:
            geometry, cells = grids.cells_of(grid)
        except ValueError as error:
            rospy.logerr("%s: ignoring a map that cannot be used: %s", self.name, error)
            return
        with self.lock:
            if geometry != self.costmap.geometry:
                rospy.loginfo("Resizing costmap to %d X %d at %f m/pix", geometry.width, geometry.height,
                              geometry.resolution)
            self.costmap.set_map(geometry, cells)
            self._dirty = True
        rospy.loginfo("Received a %d X %d map at %f m/pix", geometry.width, geometry.height, geometry.resolution)
        self._map_received.set()

    # --- the laser ----------------------------------------------------------------------------------------
    def _on_scan(self, scan, source):
        try:
            sensor = poses.from_transform(self._tf.lookup_transform(
                self.config.global_frame, scan.header.frame_id, scan.header.stamp,
                rospy.Duration(self.config.transform_tolerance)))
        except (tf2_ros.LookupException, tf2_ros.ConnectivityException, tf2_ros.ExtrapolationException,
                tf2_ros.TimeoutException):
            return
        ranges = np.asarray(scan.ranges, dtype=float)
        angles = scan.angle_min + scan.angle_increment * np.arange(len(ranges))
        usable = np.isfinite(ranges) & (ranges >= scan.range_min)
        ranges, angles = ranges[usable], angles[usable]
        heading = sensor[2] + angles
        ends = np.column_stack((sensor[0] + ranges * np.cos(heading), sensor[1] + ranges * np.sin(heading)))
        hit = (ranges < scan.range_max) if source.marking else np.zeros(len(ranges), bool)
        with self.lock:
            self._scans.append((sensor[:2], ends, hit, source.clearing))

    # --- the grid -----------------------------------------------------------------------------------------
    def robot_pose(self):
        """(x, y, yaw) of the robot in the global frame now, or None without TF."""
        try:
            return poses.from_transform(self._tf.lookup_transform(
                self.config.global_frame, self.config.robot_base_frame, rospy.Time(0),
                rospy.Duration(self.config.transform_tolerance)))
        except (tf2_ros.LookupException, tf2_ros.ConnectivityException, tf2_ros.ExtrapolationException,
                tf2_ros.TimeoutException):
            return None

    def update(self):
        """Apply the scans that came since the last update and recompute the grid; nothing to do (no scan, the
        robot in the same cell) costs one TF lookup."""
        pose = self.robot_pose()
        with self.lock:
            scans, self._scans = self._scans, []
            if not scans and pose is not None and self._pose is not None and self._same_cell(pose, self._pose) \
                    and not self._dirty:
                return
            self._dirty = False
            if pose is not None:
                self._pose = pose
                if self.config.rolling_window:
                    self.costmap.move_to(pose[0], pose[1])
            for origin, ends, hit, clearing in scans:
                if clearing:
                    self.costmap.add_scan(origin, ends, hit)
                else:
                    self.costmap.add_scan(origin, ends[hit], np.ones(int(hit.sum()), bool), clear=False)
            if self._pose is not None:
                self.costmap.clear_footprint(*self._pose)
            self.costmap.update()
        if pose is not None:
            self._publish_footprint(pose)

    def _same_cell(self, a, b):
        g = self.costmap.geometry
        return g.world_to_cell(a[0], a[1]) == g.world_to_cell(b[0], b[1]) and abs(a[2] - b[2]) < 0.05

    def reset(self):
        with self.lock:
            self.costmap.reset()
            self.costmap.update()

    def clear_outside(self, size, layer_names):
        pose = self._pose
        if pose is None:
            return
        with self.lock:
            self.costmap.clear_outside(pose[0], pose[1], size, layer_names)
            self.costmap.update()

    # --- publishing ---------------------------------------------------------------------------------------
    def grid_message(self):
        with self.lock:
            geometry, costs = self.costmap.geometry, self.costmap.costs
        if costs.size <= 1:
            return None
        return grids.grid_message(geometry, to_occupancy(costs), self.config.global_frame, rospy.Time.now())

    def publish(self):
        if self._grid_pub.get_num_connections() == 0:
            return
        with self.lock:
            geometry, costs = self.costmap.geometry, self.costmap.costs
        previous = self._published
        if previous is not None and previous[1] is costs:
            return
        self._published = (geometry, costs)
        if previous is None or previous[0] != geometry:
            message = grids.grid_message(geometry, to_occupancy(costs), self.config.global_frame, rospy.Time.now())
            publish_unless_shut_down(self._grid_pub.publish, message)
            return
        box = changed_box(previous[1], costs)
        if box is None:
            return
        col, row, width, height = box
        update = OccupancyGridUpdate()
        update.header.frame_id, update.header.stamp = self.config.global_frame, rospy.Time.now()
        update.x, update.y, update.width, update.height = col, row, width, height
        update.data = to_occupancy(costs[row:row + height, col:col + width]).ravel().tolist()
        publish_unless_shut_down(self._update_pub.publish, update)

    def _publish_footprint(self, pose):
        if not self._footprint_pub.get_num_connections():
            return
        message = PolygonStamped()
        message.header.frame_id, message.header.stamp = self.config.global_frame, rospy.Time.now()
        message.polygon.points = [Point32(x, y, 0.0) for x, y in self.config.params.footprint.placed(*pose)]
        publish_unless_shut_down(self._footprint_pub.publish, message)
