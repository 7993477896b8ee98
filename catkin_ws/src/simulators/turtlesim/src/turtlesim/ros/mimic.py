"""mimic (imports rospy): one turtle copies another's motion.

Node `turtle_mimic`. Subscribes turtlesim/Pose on input/pose and publishes geometry_msgs/Twist
on output/cmd_vel (queue 1 each): for every Pose one Twist with linear.x = linear_velocity and
angular.z = angular_velocity, zeros included. `input` and `output` are namespaces meant to be
remapped, e.g. `rosrun turtlesim mimic input:=turtlesim1/turtle1 output:=turtlesim2/turtle1`.
roscpp remaps a NodeHandle namespace; rospy remaps whole names only, so the node resolves
`input` and `output` through the command-line remappings itself, then appends /pose and
/cmd_vel. Quirk kept: linear_velocity is a magnitude, so a leader driving backwards makes the
follower drive forwards.
"""
import rospy
from geometry_msgs.msg import Twist

from roscpp_console.handler import use_roscpp_console
from turtlesim.msg import Pose

NODE_NAME = 'turtle_mimic'


class Mimic:
    """Republishes each Pose from `input_ns` as a Twist to `output_ns` (resolved namespaces)."""

    def __init__(self, input_ns, output_ns):
        self._cmd_vel = rospy.Publisher(output_ns + '/cmd_vel', Twist, queue_size=1)
        self._pose = rospy.Subscriber(input_ns + '/pose', Pose, self._on_pose, queue_size=1)

    def _on_pose(self, pose):
        command = Twist()
        command.linear.x = pose.linear_velocity
        command.angular.z = pose.angular_velocity
        self._cmd_vel.publish(command)


def main():
    """Run the node until shutdown; returns the exit code."""
    rospy.init_node(NODE_NAME)
    use_roscpp_console()
    Mimic(rospy.resolve_name('input'), rospy.resolve_name('output'))
    rospy.spin()
    return 0
