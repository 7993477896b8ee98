"""draw_square (imports rospy): calls reset, then drives turtle1 around a 2 m square for ever.

Node `draw_square`. Calls the `reset` service (std_srvs/Empty) once at start, without waiting
for it (a failed call is logged and the node carries on, as the original ignores the result).
Then subscribes turtle1/pose and, every 0.016 s of ROS time (rospy.Timer), publishes at most one
geometry_msgs/Twist on turtle1/cmd_vel as the SquareDriver decides. Logs `New goal [x y, theta]`
and `Reached goal` at INFO.
"""
import rospy
from geometry_msgs.msg import Twist
from std_srvs.srv import Empty

from roscpp_console.handler import use_roscpp_console
from turtlesim.core.draw_square import SquareDriver
from turtlesim.msg import Pose
from turtlesim.ros.log import ros_log

NODE_NAME = 'draw_square'

TIMER_PERIOD_S = 0.016


class SquareNode:
    """The tutorial's wiring: latest pose in, the driver's commands out."""

    def __init__(self):
        self._driver = SquareDriver(ros_log)
        self._pose = None
        self._cmd_vel = rospy.Publisher('turtle1/cmd_vel', Twist, queue_size=1)
        call_reset()
        # Subscribed after the reset, so no pose from before it can seed the first goal.
        self._pose_sub = rospy.Subscriber('turtle1/pose', Pose, self._on_pose, queue_size=1)
        self._timer = rospy.Timer(rospy.Duration(TIMER_PERIOD_S), self._on_timer)

    def _on_pose(self, pose):
        self._pose = pose

    def _on_timer(self, event):
        command = self._driver.on_timer(self._pose)
        if command is None:
            return
        message = Twist()
        message.linear.x, message.angular.z = command
        self._cmd_vel.publish(message)


def call_reset():
    """Call `reset` once; log a warning instead of failing when it is not there."""
    try:
        rospy.ServiceProxy('reset', Empty)()
    except (rospy.ServiceException, rospy.ROSException) as error:
        rospy.logwarn('Could not call %s: %s', rospy.resolve_name('reset'), error)


def main():
    """Run the node until shutdown; returns the exit code."""
    rospy.init_node(NODE_NAME)
    use_roscpp_console()
    SquareNode()
    rospy.spin()
    return 0
