"""The navigation panel: what RViz's turtlebot3_navigation view shows of amcl and move_base, each in its own frame
(the page places odom-frame items through map -> odom): the global and local costmaps (full grids and their
costmap_updates patches, in RViz's costmap colours), the global plan (NavfnROS/plan) and the local plan
(DWAPlannerROS/local_plan), amcl's particle cloud and pose with its covariance, move_base's current goal and
explore_lite's frontiers (explore/frontiers: POINTS of each frontier's cells and a SPHERE at each, by marker id,
DELETE and DELETEALL honoured as RViz's MarkerArray display does). Each topic is the picked robot's own where it
publishes one (/tb3_0/move_base/..., /tb3_0/particlecloud), else the global one (ros_context.own_or_global); a
display keeps what it shows until the new topic's first message replaces it (amcl and move_base latch theirs or
send them within a second)."""
import threading

import genpy
import numpy as np
from geometry_msgs.msg import PoseArray, PoseStamped, PoseWithCovarianceStamped
from map_msgs.msg import OccupancyGridUpdate
from nav_msgs.msg import OccupancyGrid, Path
from rospy.numpy_msg import numpy_msg
from visualization_msgs.msg import Marker, MarkerArray

from lab_web import occupancy, packed, scene
from lab_web.panels.base import Panel, Versioned
from lab_web.ros_context import FollowedSubscribers, now_s

COSTMAPS = {"global": "move_base/global_costmap/costmap", "local": "move_base/local_costmap/costmap"}
PLANS = {"global": "move_base/NavfnROS/plan", "local": "move_base/DWAPlannerROS/local_plan"}
COSTMAP_PERIOD_S = 0.5
"""A costmap's picture is redrawn at most twice a second (move_base patches it or sends it whole at 5-10 Hz)."""
NAV_PERIOD_S = 0.2
"""The plans, particles, amcl pose, goal and frontiers go out at most 5 times a second (the local plan alone changes
at 10 Hz), each item only when it changed: amcl's cloud of thousands of poses is not sent again with every plan."""
MAX_PLAN_POINTS = 2000
MAX_PARTICLES = 5000
MARKER_KINDS = {Marker.POINTS: "points", Marker.SPHERE: "sphere"}
NAV_ITEMS = ("plans global", "plans local", "particles", "amcl", "goal", "frontiers")
"""The nav frame's items: "<key>" or "plans <name>" (the plans frame's entry `name`)."""
NumpyOccupancyGrid, NumpyOccupancyGridUpdate = numpy_msg(OccupancyGrid), numpy_msg(OccupancyGridUpdate)
"""The grids' cells as one numpy array each (genpy's classes unpack a tuple of ints, cell by cell)."""


class PackedPoseArray(PoseArray):
    """geometry_msgs/PoseArray (its type and md5sum, so rospy connects it to any PoseArray publisher) read by
    lab_web.packed: `packed` holds the frame and the first MAX_PARTICLES poses, no genpy Pose is built."""

    __slots__ = ("packed",)

    def deserialize(self, data):
        try:
            self.packed = packed.unpack_pose_array(memoryview(data), MAX_PARTICLES)
        except ValueError as error:
            raise genpy.DeserializationError(str(error)) from None   # rospy logs it and reads the next message
        return self


def _pose(pose):
    return [round(pose.position.x, 3), round(pose.position.y, 3),
            round(scene.yaw_of(pose.orientation.z, pose.orientation.w), 4)]


def _frame(header):
    return header.frame_id.lstrip("/")


class Throttle:
    """At most one publication per `period_s` of wall time; a change within it is left pending for the next look."""

    def __init__(self, period_s):
        self.period_s = period_s
        self.last = None
        self.pending = False

    def ready(self, force=False):
        """Whether to publish now (always when `force`); if not, the change is pending."""
        now = now_s()
        if not force and self.last is not None and now - self.last < self.period_s:
            self.pending = True
            return False
        self.last, self.pending = now, False
        return True


class Costmap:
    """One costmap as cells, patched by its updates."""

    def __init__(self):
        self.info = None
        self.frame = ""
        self.cells = None
        self.throttle = Throttle(COSTMAP_PERIOD_S)

    def replace(self, grid):
        """A whole grid (a copy: the updates write into it); cells that do not add up to its size stay flat, and
        its picture is an error naming them. Whether its picture changed: move_base sends a costmap whole at its
        publish_frequency, the same grid again while the robot stands still."""
        cells = np.array(grid.data, dtype=np.int8)
        if cells.size == grid.info.width * grid.info.height:
            cells = cells.reshape(grid.info.height, grid.info.width)
        old = self.info
        changed = old is None or self.frame != _frame(grid.header) or (old.width, old.height, old.resolution) != (
            grid.info.width, grid.info.height, grid.info.resolution) or old.origin != grid.info.origin \
            or not np.array_equal(self.cells, cells)
        self.info, self.frame, self.cells = grid.info, _frame(grid.header), cells
        return changed

    def patch(self, update):
        """Writes a costmap_updates patch into the cells; whether that changed a cell (move_base's global costmap
        sends the patch of its sensors' reach at every update, mostly the same cells). A patch that does not fit the
        grid is ignored."""
        if self.cells is None or self.cells.ndim != 2 or update.x + update.width > self.cells.shape[1] \
                or update.y + update.height > self.cells.shape[0] or len(update.data) != update.width * update.height:
            return False
        region = self.cells[update.y:update.y + update.height, update.x:update.x + update.width]
        cells = np.asarray(update.data, dtype=np.int8).reshape(update.height, update.width)
        if np.array_equal(region, cells):
            return False
        region[:] = cells
        return True

    def content(self):
        info = self.info
        try:
            png = occupancy.grid_png(self.cells.tobytes(), info.width, info.height, "costmap")
        except ValueError as error:
            return {"error": str(error)}
        return {"frame": self.frame, "width": info.width, "height": info.height, "resolution": info.resolution,
                "origin": _pose(info.origin), "png": png}


class NavPanel(Panel):
    name = "nav"
    FRAMES = {
        "costmap": '{"name": "global" | "local", "frame", "width", "height", "resolution", "origin": [x, y, yaw], '
                   '"png": RGBA, a pixel per cell, row 0 first, RViz\'s costmap colours (free transparent, lethal '
                   'purple, inscribed cyan)} | {"name", "error"}  with the costmap and its updates, <= 2 per second',
        "nav": '{"plans": {"global" | "local": {"frame", "points": [[x, y], ...]}}, "particles": {"frame", "count", '
               '"poses": base64 of little-endian float32 x, y, yaw per pose}, "amcl": {"frame", "pose": [x, y, yaw], '
               '"covariance": [xx, xy, yy, yaw-yaw]}, "goal": {"frame", "pose": [x, y, yaw]}, "frontiers": [{"frame", '
               '"kind": "points" | "sphere", "rgba": [r, g, b, a] 0-1, "scale": m, "points": [[x, y], ...]}]}  only '
               'the items (each plan an item) that changed since the page\'s last nav frame, which it keeps the '
               'others of; <= 5 per second',
    }

    def __init__(self, ros):
        super().__init__(ros)
        self._lock = threading.Lock()
        self._costmaps = {name: Costmap() for name in COSTMAPS}
        self.costmaps = {name: Versioned() for name in COSTMAPS}
        self.items = {item: Versioned() for item in NAV_ITEMS}
        self._staged = {}        # item -> its value changed since the last publication (NAV_PERIOD_S)
        self._frontiers = {}     # (ns, id) -> the page's marker
        self._nav_throttle = Throttle(NAV_PERIOD_S)
        specs = []
        for name, topic in COSTMAPS.items():
            specs += [(topic, NumpyOccupancyGrid, lambda grid, _topic, name=name: self._on_costmap(grid, name),
                       {"queue_size": 1, "buff_size": 2 ** 24}),
                      (topic + "_updates", NumpyOccupancyGridUpdate,
                       lambda update, _topic, name=name: self._on_costmap_update(update, name),
                       {"queue_size": 5, "buff_size": 2 ** 24})]
        for name, topic in PLANS.items():
            specs.append((topic, Path, lambda path, _topic, name=name: self._on_plan(path, name), {"queue_size": 1}))
        specs += [
            ("particlecloud", PackedPoseArray, lambda cloud, _topic: self._on_particles(cloud),
             {"queue_size": 1, "buff_size": 2 ** 24}),
            ("amcl_pose", PoseWithCovarianceStamped, lambda pose, _topic: self._on_amcl_pose(pose), {"queue_size": 1}),
            ("move_base/current_goal", PoseStamped, lambda goal, _topic: self._on_goal(goal), {"queue_size": 1}),
            ("explore/frontiers", MarkerArray, lambda array, _topic: self._on_frontiers(array), {"queue_size": 1}),
        ]
        self._followed = FollowedSubscribers(ros, specs, self._on_switch)

    def on_graph(self, graph):
        self._followed.on_graph(graph)

    def _on_switch(self, relative, _topic):
        """A costmap now comes from another robot's move_base: its first grid goes out at once."""
        for name, topic in COSTMAPS.items():
            if relative == topic:
                with self._lock:
                    self._costmaps[name] = Costmap()

    def frames(self, session):
        with self._lock:
            for name, costmap in self._costmaps.items():
                if costmap.throttle.pending:
                    self._publish_costmap(name)   # a patch that came within COSTMAP_PERIOD_S of the last picture
            if self._nav_throttle.pending:
                self._publish_nav()
        out = self.lacking(session, *(("costmap", versioned, "costmap " + name)
                                      for name, versioned in self.costmaps.items()))
        nav = {}
        for item, versioned in self.items.items():
            content = session.lacks("nav " + item, versioned)
            if content is not None:
                key, _, plan = item.partition(" ")
                if plan:
                    nav.setdefault(key, {})[plan] = content
                else:
                    nav[key] = content
        return out + [("nav", nav)] if nav else out

    def _on_costmap(self, grid, name):
        """A whole grid: the first goes out at once, later ones at most every COSTMAP_PERIOD_S as the patches do
        (move_base's rolling local costmap comes whole at its publish_frequency, 10 Hz in turtlebot3_navigation)."""
        with self._lock:
            costmap = self._costmaps[name]
            first = costmap.info is None
            if costmap.replace(grid):
                self._publish_costmap(name, force=first)

    def _on_costmap_update(self, update, name):
        with self._lock:
            if self._costmaps[name].patch(update):
                self._publish_costmap(name)

    def _publish_costmap(self, name, force=False):
        costmap = self._costmaps[name]
        if costmap.throttle.ready(force):
            self.costmaps[name].set(dict(costmap.content(), name=name))

    def _publish_nav(self):
        if self._nav_throttle.ready():
            for item, value in self._staged.items():
                self.items[item].set(value)
            self._staged.clear()

    def _set(self, item, value):
        with self._lock:
            self._staged[item] = value
            self._publish_nav()

    def _on_plan(self, path, name):
        points = [[round(stamped.pose.position.x, 3), round(stamped.pose.position.y, 3)]
                  for stamped in path.poses[:MAX_PLAN_POINTS]]
        self._set("plans " + name, {"frame": _frame(path.header), "points": points})

    def _on_particles(self, cloud):
        cloud = cloud.packed
        self._set("particles", {"frame": cloud.frame_id.lstrip("/"), "count": len(cloud.poses),
                                "poses": cloud.base64()})

    def _on_amcl_pose(self, message):
        c = message.pose.covariance
        self._set("amcl", {"frame": _frame(message.header), "pose": _pose(message.pose.pose),
                           "covariance": [c[0], c[1], c[7], c[35]]})

    def _on_goal(self, goal):
        self._set("goal", {"frame": _frame(goal.header), "pose": _pose(goal.pose)})

    def _on_frontiers(self, array):
        with self._lock:
            for marker in array.markers:
                key = (marker.ns, marker.id)
                if marker.action == Marker.DELETEALL:
                    self._frontiers.clear()
                elif marker.action == Marker.DELETE:
                    self._frontiers.pop(key, None)
                elif marker.type in MARKER_KINDS:
                    points = [[round(marker.pose.position.x + point.x, 3), round(marker.pose.position.y + point.y, 3)]
                              for point in marker.points] or [[round(marker.pose.position.x, 3),
                                                                round(marker.pose.position.y, 3)]]
                    color = marker.color
                    self._frontiers[key] = {"frame": _frame(marker.header), "kind": MARKER_KINDS[marker.type],
                                            "rgba": [color.r, color.g, color.b, color.a],
                                            "scale": marker.scale.x, "points": points}
            frontiers = list(self._frontiers.values())
        self._set("frontiers", frontiers)
