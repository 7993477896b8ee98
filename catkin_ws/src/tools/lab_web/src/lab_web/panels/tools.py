"""The tools panel: RViz's tools that publish, driven by drags on the page's top view, and a cancel-goal button.

As RViz publishes them (rviz/default_plugin/tools): "2D Pose Estimate" -> /initialpose
(geometry_msgs/PoseWithCovarianceStamped, the fixed frame, covariance x and y 0.5^2 = 0.25 and yaw (pi/12)^2, the
rest 0), "2D Nav Goal" -> /move_base_simple/goal (geometry_msgs/PoseStamped, the fixed frame: map with a map),
"Publish Point" -> /clicked_point (geometry_msgs/PointStamped, z 0 on the ground). RViz has no cancel button; the
lab's publishes an empty actionlib_msgs/GoalID on /move_base/cancel, which cancels every goal (what
`rostopic pub /move_base/cancel actionlib_msgs/GoalID -- {}` does). The publishers exist from the start, as RViz's
do, so the first drag reaches amcl and move_base (a new publisher's first message is lost)."""
import math

from actionlib_msgs.msg import GoalID
from geometry_msgs.msg import PointStamped, PoseStamped, PoseWithCovarianceStamped

from lab_web import commands
from lab_web.panels.base import Panel

INITIAL_POSE_COVARIANCE = {0: 0.5 ** 2, 7: 0.5 ** 2, 35: (math.pi / 12.0) ** 2}
"""Row-major 6 x 6 (x, y, z, roll, pitch, yaw): RViz's 2D Pose Estimate."""
PLACE = (("frame", commands.name), ("x", commands.coordinate()), ("y", commands.coordinate()))
POSE = PLACE + (("yaw", commands.number(math.pi)),)


def _pose(pose, x, y, yaw):
    pose.position.x, pose.position.y = x, y
    pose.orientation.z, pose.orientation.w = math.sin(yaw / 2.0), math.cos(yaw / 2.0)


class ToolsPanel(Panel):
    name = "tools"
    COMMANDS = {
        "initial_pose": commands.CommandSpec(POSE, "2D Pose Estimate: /initialpose at (x, y) facing yaw in frame"),
        "nav_goal": commands.CommandSpec(POSE, "2D Nav Goal: /move_base_simple/goal at (x, y) facing yaw in frame"),
        "publish_point": commands.CommandSpec(PLACE, "Publish Point: /clicked_point (x, y, 0) in frame"),
        "cancel_goal": commands.CommandSpec((), "an empty GoalID on /move_base/cancel: every goal is cancelled"),
    }

    def __init__(self, ros):
        super().__init__(ros)
        self._publishers = {
            "initial_pose": ros.publisher("/initialpose", PoseWithCovarianceStamped),
            "nav_goal": ros.publisher("/move_base_simple/goal", PoseStamped),
            "publish_point": ros.publisher("/clicked_point", PointStamped),
            "cancel_goal": ros.publisher(ros.name("move_base/cancel"), GoalID),
        }

    def handle(self, session, kind, args):
        if kind == "initial_pose":
            message = PoseWithCovarianceStamped()
            _pose(message.pose.pose, args["x"], args["y"], args["yaw"])
            message.pose.covariance = [INITIAL_POSE_COVARIANCE.get(i, 0.0) for i in range(36)]
        elif kind == "nav_goal":
            message = PoseStamped()
            _pose(message.pose, args["x"], args["y"], args["yaw"])
        elif kind == "publish_point":
            message = PointStamped()
            message.point.x, message.point.y = args["x"], args["y"]
        else:
            message = GoalID()
        if kind != "cancel_goal":
            message.header.frame_id = args["frame"]
            message.header.stamp = self.ros.now()
        self._publishers[kind].publish(message)
