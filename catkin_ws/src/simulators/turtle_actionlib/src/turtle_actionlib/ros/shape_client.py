"""shape_client (imports rospy): asks shape_server for a pentagon and reports how it ended.

Node `test_shape`. An action client on `turtle_shape` waits for the server (for ever), logs
`Waiting for action server to start.` and `Action server started, sending goal.`, sends
edges = 5, radius = 1.3 and waits up to 40 s of ROS time. Then it logs
`Action finished: <STATE>` (e.g. SUCCEEDED) or `Action did not finish before the time out.`
and exits with 0, as the original does either way.
"""
import actionlib
import rospy
from actionlib_msgs.msg import GoalStatus

from turtle_actionlib.msg import ShapeAction, ShapeGoal

NODE_NAME = 'test_shape'
ACTION_NAME = 'turtle_shape'
EDGES = 5
RADIUS_M = 1.3
RESULT_TIMEOUT_S = 40.0

STATE_NAMES = {getattr(GoalStatus, name): name for name in (
    'PENDING', 'ACTIVE', 'PREEMPTED', 'SUCCEEDED', 'ABORTED', 'REJECTED', 'RECALLED', 'LOST')}
"""SimpleActionClient.get_state() values and their names, as SimpleClientGoalState::toString."""


def main():
    """Run the client once; returns the exit code."""
    rospy.init_node(NODE_NAME)
    client = actionlib.SimpleActionClient(ACTION_NAME, ShapeAction)
    rospy.loginfo('Waiting for action server to start.')
    client.wait_for_server()
    rospy.loginfo('Action server started, sending goal.')
    client.send_goal(ShapeGoal(edges=EDGES, radius=RADIUS_M))
    if client.wait_for_result(rospy.Duration(RESULT_TIMEOUT_S)):
        rospy.loginfo('Action finished: %s', STATE_NAMES.get(client.get_state(), 'UNKNOWN'))
    else:
        rospy.loginfo('Action did not finish before the time out.')
    return 0
