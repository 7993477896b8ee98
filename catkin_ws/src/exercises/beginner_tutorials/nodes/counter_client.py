#!/usr/bin/env python3
"""counter_client.py [NUM_COUNTS] [--cancel-after SECONDS]: sends a counter goal to my_action_server,
prints each feedback and then the final state and result.

Exit code 0 when the goal succeeded (or was preempted because --cancel-after asked for it), 1 otherwise:
wrong arguments (with the usage), no action server within SERVER_WAIT_S, or an aborted/rejected goal.
"""
import sys

import actionlib
import rospy

from beginner_tutorials.counter_options import parse_counter_options, usage
from beginner_tutorials.errors import UsageError
from beginner_tutorials.goal_states import client_exit_code, goal_state_name
from beginner_tutorials.msg import counterAction, counterGoal

SERVER_WAIT_S = 10.0


class CounterClient:
    def __init__(self):
        self.client = actionlib.SimpleActionClient("my_action_server", counterAction)

    def wait_for_server(self):
        return self.client.wait_for_server(rospy.Duration(SERVER_WAIT_S))

    def on_feedback(self, feedback):
        print("feedback: counts_elapsed={}".format(feedback.counts_elapsed), flush=True)

    def count(self, num_counts, cancel_after_s=None):
        """Runs one goal to its end; returns the final state's name."""
        print("sending goal: num_counts={}".format(num_counts), flush=True)
        self.client.send_goal(counterGoal(num_counts=num_counts), feedback_cb=self.on_feedback)
        if cancel_after_s is not None and not self.client.wait_for_result(rospy.Duration(cancel_after_s)):
            print("cancelling the goal after {} s".format(cancel_after_s), flush=True)
            self.client.cancel_goal()
        self.client.wait_for_result()
        state = goal_state_name(self.client.get_state())
        result = self.client.get_result()
        print("state: {}".format(state))
        print("result: {}".format(result.result_message if result else "(none)"))
        return state


def main():
    try:
        options = parse_counter_options(rospy.myargv(argv=sys.argv)[1:])
    except UsageError as error:
        print("error: {}\n{}".format(error, usage("counter_client.py")), file=sys.stderr)
        return 1
    rospy.init_node("counter_action_client", anonymous=True)
    client = CounterClient()
    if not client.wait_for_server():
        print("error: no action server my_action_server after {} s (is counter_server.py running?)".format(
            SERVER_WAIT_S), file=sys.stderr)
        return 1
    try:
        state = client.count(options.num_counts, options.cancel_after_s)
    except rospy.ROSInterruptException:
        return 1
    return client_exit_code(state, options.cancel_after_s is not None)


if __name__ == "__main__":
    sys.exit(main())
