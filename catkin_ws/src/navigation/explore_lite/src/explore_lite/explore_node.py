"""explore_lite's `explore` node: frontier exploration through move_base, over lab_nav.exploration.

~params with the code's defaults (launch/explore*.launch set the original launch files' values):
robot_base_frame (base_link), costmap_topic (costmap), costmap_updates_topic (costmap_updates), visualize
(false), planner_frequency (1.0 Hz), progress_timeout (30.0 s), potential_scale (0.001), orientation_scale (0.0,
unused as in the original), gain_scale (1.0), transform_tolerance (0.3 s), min_frontier_size (0.5 m). Bad values
(not numbers, a frequency or size <= 0) are an ERROR naming the parameter and exit code 1.

Start-up as the original: its own lines are logged at DEBUG (so "found N frontiers" and the cost lines show);
it waits for the first costmap ("Waiting for costmap to become available, topic: map"), then for the transform
from the map's frame to robot_base_frame (a warning every 5 s), then for move_base ("Waiting to connect to
move_base server" / "Connected to move_base server"). Then every 1/planner_frequency s, and at once when a goal
ends, it searches the frontiers from the robot's position, publishes ~frontiers, and sends move_base the chosen
centroid (frame of the map, orientation w = 1). With no frontier left it cancels all goals and logs "Exploration
stopped."; the node stays up. Chosen where the original misbehaves: a robot pose older than transform_tolerance
skips the step with its warning, where the original would search from the map's (0, 0). Console lines are in
roscpp's format.
"""

import logging
import threading

import actionlib
import numpy as np
import rospy
import tf2_ros
from actionlib import CommState
from actionlib_msgs.msg import GoalStatus
from map_msgs.msg import OccupancyGridUpdate
from move_base_msgs.msg import MoveBaseAction, MoveBaseGoal
from nav_msgs.msg import OccupancyGrid
from nav_ros.sim_clock import PeriodicThread
from visualization_msgs.msg import MarkerArray

from explore_lite.markers import frontier_markers
from lab_nav.exploration.blacklist import on_blacklist
from lab_nav.exploration.costmap_codes import apply_update, costmap_codes
from lab_nav.exploration.explorer import BLACKLISTED, SEND, STOP, Explorer
from lab_nav.exploration.frontier_search import OUT_OF_BOUNDS, FrontierSearch
from lab_nav.maps.geometry import MapGeometry
from lab_nav.planning.periodic import PeriodicTasks
from roscpp_console.handler import use_roscpp_console
from sim_clock import quiet_time_notifications

EXIT_BAD_PARAMETER = 1
TF_CACHE_S = 10.0
TF_WAIT_STEP_S = 0.1
TF_WARNING_EVERY_S = 5.0
THROTTLE_S = 1.0
# explore's own lines go to this logger, set to DEBUG as the original sets its package's logger, so that rospy's
# internal debug lines stay hidden (roscpp's stay hidden in the original too)
LOGGER_NAME = "explore_lite"
STATUS_NAMES = {value: name for name, value in vars(GoalStatus).items() if name.isupper() and isinstance(value, int)}

# name: (default, must be > 0)
NUMBER_PARAMS = {"planner_frequency": (1.0, True), "progress_timeout": (30.0, False),
                 "potential_scale": (1e-3, False), "orientation_scale": (0.0, False), "gain_scale": (1.0, False),
                 "transform_tolerance": (0.3, False), "min_frontier_size": (0.5, True)}
TEXT_PARAMS = {"robot_base_frame": "base_link", "costmap_topic": "costmap",
               "costmap_updates_topic": "costmap_updates"}


def debug(text, *args):
    rospy.logdebug(text, *args, logger_name=LOGGER_NAME)


class ParameterError(ValueError):
    """A ~param with a value explore cannot use; the text names it."""


def read_params():
    """The node's ~params as a dict, checked; raises ParameterError."""
    params = {}
    for name, (default, positive) in NUMBER_PARAMS.items():
        value = rospy.get_param("~" + name, default)
        if isinstance(value, bool) or not isinstance(value, (int, float)) or (positive and value <= 0):
            raise ParameterError("~{} must be a {}number, got {!r}".format(name, "positive " if positive else "",
                                                                          value))
        params[name] = float(value)
    for name, default in TEXT_PARAMS.items():
        value = rospy.get_param("~" + name, default)
        if not isinstance(value, str) or not value:
            raise ParameterError("~{} must be a non-empty string, got {!r}".format(name, value))
        params[name] = value
    visualize = rospy.get_param("~visualize", False)
    if not isinstance(visualize, bool):
        raise ParameterError("~visualize must be true or false, got {!r}".format(visualize))
    params["visualize"] = visualize
    return params


class CostmapClient:
    """The map as costmap codes, kept up to date from the full grids and the partial updates, and the robot's
    position in the map's frame."""

    def __init__(self, params):
        self._lock = threading.Lock()
        self._base_frame = params["robot_base_frame"]
        self._tolerance_s = params["transform_tolerance"]
        self._tf = tf2_ros.Buffer(rospy.Duration(TF_CACHE_S))
        self._listener = tf2_ros.TransformListener(self._tf)
        self.frame_id, self.geometry, self.codes = None, None, None
        rospy.loginfo("Waiting for costmap to become available, topic: %s", params["costmap_topic"])
        self._on_map(rospy.wait_for_message(params["costmap_topic"], OccupancyGrid))
        self._map_subscriber = rospy.Subscriber(params["costmap_topic"], OccupancyGrid, self._on_map,
                                                queue_size=1000)
        self._update_subscriber = rospy.Subscriber(params["costmap_updates_topic"], OccupancyGridUpdate,
                                                   self._on_update, queue_size=1000)

    def _on_map(self, message):
        info = message.info
        debug("received full new map, resizing to: %d, %d", info.width, info.height)
        codes = np.full((info.height, info.width), costmap_codes([-1])[0], np.uint8)
        count = min(len(message.data), info.width * info.height)
        codes.ravel()[:count] = costmap_codes(np.asarray(message.data[:count], dtype=np.int64))
        geometry = MapGeometry(resolution=info.resolution, width=info.width, height=info.height,
                               origin_x=info.origin.position.x, origin_y=info.origin.position.y)
        with self._lock:
            self.frame_id, self.geometry, self.codes = message.header.frame_id, geometry, codes
        debug("full map update, %d values", codes.size)

    def _on_update(self, message):
        debug("received partial map update")
        with self._lock:
            self.frame_id = message.header.frame_id
            problem = apply_update(self.codes, message.x, message.y, message.width, message.height, message.data)
        if problem:
            (rospy.logerr if problem.startswith(("negative", "invalid")) else rospy.logwarn)(problem)

    def snapshot(self):
        """(frame_id, geometry, a copy of the codes), consistent with each other."""
        with self._lock:
            return self.frame_id, self.geometry, self.codes.copy()

    def wait_for_transform(self):
        last_warning = rospy.get_time()
        while not rospy.is_shutdown():
            try:
                self._tf.lookup_transform(self.frame_id, self._base_frame, rospy.Time(0),
                                          rospy.Duration(TF_WAIT_STEP_S))
                return
            except tf2_ros.TransformException as error:
                if rospy.get_time() - last_warning > TF_WARNING_EVERY_S:
                    rospy.logwarn("Timed out waiting for transform from %s to %s to become available before "
                                  "subscribing to costmap, tf error: %s", self._base_frame, self.frame_id, error)
                    last_warning = rospy.get_time()

    def robot_position(self, frame_id):
        """(x, y) of robot_base_frame in `frame_id`, or None (logged) when unknown or older than the tolerance."""
        now = rospy.get_rostime()
        try:
            transform = self._tf.lookup_transform(frame_id, self._base_frame, rospy.Time(0))
        except tf2_ros.TransformException as error:
            rospy.logerr_throttle(THROTTLE_S, "No Transform available Error looking up robot pose: {}".format(error))
            return None
        stamp = transform.header.stamp
        if now.to_sec() - stamp.to_sec() > self._tolerance_s:
            rospy.logwarn_throttle(THROTTLE_S, "Costmap2DClient transform timeout. Current time: %.4f, global_pose "
                                   "stamp: %.4f, tolerance: %.4f" % (now.to_sec(), stamp.to_sec(), self._tolerance_s))
            return None
        return transform.transform.translation.x, transform.transform.translation.y


class Explore:
    """The planning loop: frontier search, markers, goals to move_base."""

    def __init__(self, params):
        self._params = params
        self._timer = None
        self._plan_lock = threading.Lock()
        self._explorer = Explorer(params["progress_timeout"])
        self._marker_count = 0
        self._costmap = CostmapClient(params)
        self._costmap.wait_for_transform()
        self._markers = (rospy.Publisher("~frontiers", MarkerArray, queue_size=10) if params["visualize"]
                         else None)
        self._goal = None   # the handle of the goal last sent; the others' transitions are ignored
        self._goal_lock = threading.Lock()
        self._move_base = actionlib.ActionClient("move_base", MoveBaseAction)
        rospy.loginfo("Waiting to connect to move_base server")
        while not self._move_base.wait_for_server(rospy.Duration(1.0)):
            if rospy.is_shutdown():
                return
        rospy.loginfo("Connected to move_base server")
        planning = PeriodicTasks()
        planning.add(1.0 / params["planner_frequency"], self.make_plan, first_after_period=True)
        self._timer = PeriodicThread(planning, "explore_planner")

    def make_plan(self):
        with self._plan_lock:
            self._make_plan()

    def _make_plan(self):
        frame_id, geometry, codes = self._costmap.snapshot()
        position = self._costmap.robot_position(frame_id)
        if position is None:
            return
        params = self._params
        search = FrontierSearch(codes, geometry, params["potential_scale"], params["gain_scale"],
                                params["min_frontier_size"]).search_from(*position)
        if search.message == OUT_OF_BOUNDS:
            rospy.logerr(search.message)
        elif search.message:
            rospy.logwarn(search.message)
        frontiers = search.frontiers
        debug("found %d frontiers", len(frontiers))
        for index, frontier in enumerate(frontiers):
            debug("frontier %d cost: %f", index, frontier.cost)
        if frontiers and self._markers is not None:
            array, self._marker_count = frontier_markers(
                frontiers, lambda point: on_blacklist(point, self._explorer.blacklist, geometry.resolution),
                frame_id, rospy.Time.now(), self._marker_count)
            self._markers.publish(array)
        step = self._explorer.step(frontiers, geometry.resolution, rospy.get_time())
        for _ in step.blacklisted:
            debug(BLACKLISTED)
        if step.action == STOP:
            self._stop()
        elif step.action == SEND:
            self._send(frame_id, step.target)

    def _send(self, frame_id, target):
        goal = MoveBaseGoal()
        goal.target_pose.header.frame_id = frame_id
        goal.target_pose.header.stamp = rospy.Time.now()
        goal.target_pose.pose.position.x, goal.target_pose.pose.position.y = target
        goal.target_pose.pose.orientation.w = 1.0
        with self._goal_lock:
            self._goal = self._move_base.send_goal(
                goal, transition_cb=lambda handle: self._transition(handle, target))

    def _transition(self, handle, target):
        """A goal's state changed. Only the goal last sent counts, as with the original's SimpleActionClient,
        which forgets the previous goal when it sends a new one. (rospy's SimpleActionClient logs an ERROR "Got a
        transition callback on a goal handle that we're not tracking" when the previous goal's status arrives in
        another thread while the new goal is sent; the C++ client runs its callbacks in one thread.)"""
        with self._goal_lock:
            if handle != self._goal or handle.get_comm_state() != CommState.DONE:
                return
            self._goal = None
        self._goal_ended(handle.get_goal_status(), target)

    def _goal_ended(self, status, target):
        debug("Reached goal with status: %s", STATUS_NAMES.get(status, status))
        if self._explorer.goal_ended(target, aborted=status == GoalStatus.ABORTED):
            debug(BLACKLISTED)
        # plan again at once (also after a stop, so "Exploration stopped." may come twice, as in the original),
        # from another thread: this callback runs inside actionlib's client
        threading.Thread(target=self.make_plan, daemon=True).start()

    def _stop(self):
        self._move_base.cancel_all_goals()
        if self._timer is not None:
            self._timer.stop()
            self._timer = None
        rospy.loginfo("Exploration stopped.")


def main():
    quiet_time_notifications()
    rospy.init_node("explore")
    use_roscpp_console()
    logging.getLogger("rosout." + LOGGER_NAME).setLevel(logging.DEBUG)
    try:
        params = read_params()
    except ParameterError as error:
        rospy.logerr(str(error))
        return EXIT_BAD_PARAMETER
    try:
        Explore(params)
    except rospy.ROSInterruptException:
        return 0
    rospy.spin()
    return 0
