"""shape_server (imports rospy): the turtle_actionlib ShapeAction server on turtlesim's turtle1.

Node `turtle_shape`. A SimpleActionServer named after the node's fully-resolved name (so
/turtle_shape, topics /turtle_shape/goal, cancel, status, feedback, result) with goal and
preempt callbacks, no execute callback. Subscribes /turtle1/pose and publishes /turtle1/cmd_vel
(absolute names, queue 1): one Twist per Pose while a goal is active, from turtlesim's
ShapeController (the original's controlCB). A new goal is accepted at once; its result
(interior_angle, apothem) is fixed then. After the last edge the next Pose logs
`/turtle_shape: Succeeded` and succeeds the goal. Preempt logs `/turtle_shape: Preempted`.
No feedback is published.
"""
import actionlib
import rospy
from geometry_msgs.msg import Twist

from turtle_actionlib.msg import ShapeAction, ShapeResult
from turtle_actionlib.shape_controller import PREEMPTED_LOG, SUCCEEDED_LOG, ShapeController
from turtlesim.msg import Pose

NODE_NAME = 'turtle_shape'


class ShapeServer:
    """The action server and its turtle1 wiring."""

    def __init__(self, action_name):
        self._action_name = action_name
        self._controller = None
        self._server = actionlib.SimpleActionServer(action_name, ShapeAction, auto_start=False)
        self._server.register_goal_callback(self._on_goal)
        self._server.register_preempt_callback(self._on_preempt)
        self._cmd_vel = rospy.Publisher('/turtle1/cmd_vel', Twist, queue_size=1)
        self._pose = rospy.Subscriber('/turtle1/pose', Pose, self._on_pose, queue_size=1)
        self._server.start()

    def _on_goal(self):
        goal = self._server.accept_new_goal()
        self._controller = ShapeController(goal.edges, goal.radius)

    def _on_preempt(self):
        rospy.loginfo(PREEMPTED_LOG, self._action_name)
        self._server.set_preempted()

    def _on_pose(self, pose):
        # The goal and preempt callbacks run holding the action server's locks (the
        # ActionServer's, then the SimpleActionServer's); taking them here in the same order
        # serialises this callback with them, as the original's single-threaded spinner does.
        with self._server.action_server.lock, self._server.lock:
            if not self._server.is_active():
                return
            step = self._controller.on_pose(pose)
            if step.succeeded:
                rospy.loginfo(SUCCEEDED_LOG, self._action_name)
                self._server.set_succeeded(ShapeResult(*self._controller.result))
                return
            command = Twist()
            command.linear.x, command.angular.z = step.command
            self._cmd_vel.publish(command)


def main():
    """Run the node until shutdown; returns the exit code."""
    rospy.init_node(NODE_NAME)
    ShapeServer(rospy.get_name())
    rospy.spin()
    return 0
