#!/usr/bin/env python3
"""COM2009 Week 5: the CameraSweep action client (node camera_sweep_action_client).

Waits for the /camera_sweep_action_server action server, sends one goal (a 90 degree sweep with 4 images),
prints each feedback message as it arrives, then the final state and result:

    FEEDBACK: current angle 22.6 degrees, image(s) captured so far: 1
    ...
    RESULT: state SUCCEEDED, image_path: ~/myrosdata/action_examples/20250101_120000

Exits 0 when the goal succeeded, 1 otherwise (refused, aborted, or cancelled). Ctrl-C while the goal runs
cancels it (the server stops the robot) before the node exits.

Known quirk of actionlib 1.13 (Debian's, ros/actionlib#206, unfixed upstream): SimpleActionClient sometimes logs
"[ERROR] Got a transition callback on a goal handle that we're not tracking" right after send_goal, when the
server's first status arrives before send_goal has returned. It is harmless: feedback and the result still come.
"""
import sys

import actionlib
import rospy
from actionlib_msgs.msg import GoalStatus
from tuos_msgs.msg import CameraSweepAction, CameraSweepGoal

NODE_NAME = "camera_sweep_action_client"
ACTION_NAME = "/camera_sweep_action_server"
SWEEP_ANGLE_DEG = 90.0
IMAGE_COUNT = 4
STATE_NAMES = {value: name for name, value in vars(GoalStatus).items() if name.isupper() and isinstance(value, int)}


class CameraSweepClient:
    def __init__(self):
        self.client = actionlib.SimpleActionClient(ACTION_NAME, CameraSweepAction)
        self.finished = False
        rospy.on_shutdown(self.cancel_if_running)

    def run(self):
        """Send the goal and wait for its end; returns the final GoalStatus value, or None on Ctrl-C."""
        rospy.loginfo("Waiting for the '%s' action server...", ACTION_NAME)
        if not self.client.wait_for_server():
            return None
        goal = CameraSweepGoal(sweep_angle=SWEEP_ANGLE_DEG, image_count=IMAGE_COUNT)
        rospy.loginfo("Sending a goal: %d images over %.0f degrees.", goal.image_count, goal.sweep_angle)
        self.client.send_goal(goal, feedback_cb=self.on_feedback)
        if not self.client.wait_for_result():
            return None
        self.finished = True
        return self.client.get_state()

    @staticmethod
    def on_feedback(feedback):
        print("FEEDBACK: current angle {:.1f} degrees, image(s) captured so far: {}".format(
            feedback.current_angle, feedback.current_image), flush=True)

    def cancel_if_running(self):
        if not self.finished and self.client.gh is not None:
            rospy.logwarn("Shutting down: cancelling the goal...")
            self.client.cancel_goal()


def main():
    rospy.init_node(NODE_NAME)
    client = CameraSweepClient()
    state = client.run()
    if state is None:
        print("RESULT: interrupted before the goal finished", file=sys.stderr)
        sys.exit(1)
    result = client.client.get_result()
    print("RESULT: state {}, image_path: {}".format(STATE_NAMES.get(state, state),
                                                     result.image_path if result else "(no result)"))
    sys.exit(0 if state == GoalStatus.SUCCEEDED else 1)


if __name__ == "__main__":
    main()
