#!/usr/bin/env python3
"""The counter action server (node counter_action_server, action my_action_server, beginner_tutorials/counter).

Counts once a second (rospy time), publishing counts_elapsed feedback 0, 1, ..., num_counts-1 before each
wait, and succeeds with "Counting complete!". A cancel (or a newer goal) preempts it within a second, with
the count reached in the result; num_counts below 1 is aborted with the reason in the result and status text.
"""
import actionlib
import rospy

from beginner_tutorials.counting import COMPLETE_MESSAGE, COUNT_RATE_HZ, CountingTask
from beginner_tutorials.errors import CountError
from beginner_tutorials.msg import counterAction, counterFeedback, counterResult


class CounterActionServer:
    def __init__(self):
        self.server = actionlib.SimpleActionServer("my_action_server", counterAction, execute_cb=self.execute,
                                                   auto_start=False)
        self.server.start()

    def execute(self, goal):
        try:
            task = CountingTask(goal.num_counts)
        except CountError as error:
            rospy.logwarn("Aborting goal: %s", error)
            self.server.set_aborted(counterResult(result_message=str(error)), text=str(error))
            return
        rate = rospy.Rate(COUNT_RATE_HZ)
        try:
            while not task.finished:
                if self.server.is_preempt_requested():
                    self.preempt(task)
                    return
                self.server.publish_feedback(counterFeedback(counts_elapsed=task.counts_elapsed))
                rate.sleep()
                task.advance()
        except rospy.ROSInterruptException:
            self.preempt(task)
            return
        self.server.set_succeeded(counterResult(result_message=COMPLETE_MESSAGE))

    def preempt(self, task):
        message = task.preempted_message()
        rospy.loginfo(message)
        self.server.set_preempted(counterResult(result_message=message), text=message)


def main():
    rospy.init_node("counter_action_server")
    CounterActionServer()
    rospy.spin()


if __name__ == "__main__":
    main()
