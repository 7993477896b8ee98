"""The planners' ROS side (imports rospy): NavfnROS's plan topic and make_plan service, DWAPlannerROS's plans.

NavfnROS plans on the global costmap from the robot's cell to the goal's (lab_nav.planning.global_planner,
whose goal potential is kept while the costmap does not change) and publishes every attempt on ~NavfnROS/plan
(nav_msgs/Path in the costmap's frame; empty when planning failed): cell centres with identity orientation, the
goal with its own pose last. Goals and starts must be in the costmap's frame (the original's ERROR otherwise).
DWAPlannerROS publishes the part of the global plan it follows (~DWAPlannerROS/global_plan) and the chosen
trajectory (~DWAPlannerROS/local_plan, empty when none is valid), both in the local costmap's frame (odom).
A path message is built only while someone subscribes: at 10 Hz, a few hundred poses of genpy objects cost
move_base more than the planners' own arithmetic.
"""
import numpy as np
import rospy
from geometry_msgs.msg import PoseStamped
from nav_msgs.msg import Path
from nav_ros import poses
from nav_ros.params import read

from lab_nav.planning import global_planner
from stop_request.closed_topic import publish_unless_shut_down

WRONG_FRAME = "The {} pose passed to this planner must be in the {} frame.  It is instead in the {} frame."
OFF_MAP = "The goal sent to the navfn planner is off the global costmap. Planning will always fail to this goal."


def path_message(frame, stamp, points, last_pose=None):
    """nav_msgs/Path of (x, y) points (identity orientation; headings for (x, y, yaw) rows)."""
    path = Path()
    path.header.frame_id, path.header.stamp = frame, stamp
    for point in points:
        pose = PoseStamped()
        pose.header = path.header
        pose.pose = poses.to_pose((point[0], point[1], point[2] if len(point) > 2 else 0.0))
        path.poses.append(pose)
    if last_pose is not None and path.poses:
        path.poses[-1].pose = poses.to_pose(last_pose)
    return path


class NavfnRos:
    def __init__(self, costmap):
        self.costmap = costmap
        self.allow_unknown = read("NavfnROS/allow_unknown", True, bool)
        self.default_tolerance = read("NavfnROS/default_tolerance", 0.0)
        self._navfn = global_planner.Navfn()
        self._plan_pub = rospy.Publisher("~NavfnROS/plan", Path, queue_size=1)

    @property
    def frame(self):
        return self.costmap.config.global_frame

    def check_frame(self, pose_stamped, which):
        frame = pose_stamped.header.frame_id.lstrip("/")
        if frame != self.frame:
            rospy.logerr(WRONG_FRAME.format(which, self.frame, frame))
            return False
        return True

    def plan(self, start, goal, tolerance=0.0):
        """[(x, y), ...] from start (x, y, yaw) to goal (x, y, yaw) in the costmap frame, or None."""
        with self.costmap.lock:
            geometry, costs = self.costmap.costmap.geometry, self.costmap.costmap.costs
        start_cell = tuple(int(v) for v in geometry.world_to_cell(start[0], start[1]))
        goal_cell = tuple(int(v) for v in geometry.world_to_cell(goal[0], goal[1]))
        if not geometry.contains(*goal_cell):
            rospy.logwarn_throttle(1.0, OFF_MAP)
            return None
        if not geometry.contains(*start_cell):
            rospy.logwarn("The robot's start position is off the global costmap. Planning will always fail, are "
                          "you sure the robot has been properly localized?")
            return None
        cells = self._navfn.plan(costs, start_cell, goal_cell, geometry.resolution, self.allow_unknown,
                                 int(round(tolerance / geometry.resolution)))
        if cells is None:
            return None
        x, y = geometry.cell_center([c for c, _ in cells], [r for _, r in cells])
        points = np.column_stack((x, y))
        points[0] = start[:2]
        if cells[-1] == goal_cell:
            points[-1] = goal[:2]
        return points

    def publish(self, points, goal):
        if self._plan_pub.get_num_connections():
            publish_unless_shut_down(self._plan_pub.publish, path_message(
                self.frame, rospy.Time.now(), points if points is not None else [], goal))


class DwaRos:
    def __init__(self):
        self._global_pub = rospy.Publisher("~DWAPlannerROS/global_plan", Path, queue_size=1)
        self._local_pub = rospy.Publisher("~DWAPlannerROS/local_plan", Path, queue_size=1)

    def publish(self, frame, plan_points, trajectory):
        stamp = rospy.Time.now()
        for publisher, points in ((self._global_pub, plan_points), (self._local_pub, trajectory)):
            if publisher.get_num_connections():
                publish_unless_shut_down(publisher.publish, path_message(frame, stamp, points))
