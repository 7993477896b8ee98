#!/usr/bin/env python3
"""COM2009 Part 5: the Search action server (node search_action_server, action /search_action_server, type
tuos_msgs/Search).

A goal asks the robot to drive straight ahead at `fwd_velocity` m/s and stop `approach_distance` m from the closest
object ahead (LiDAR arc of +-20 degrees). While it drives, feedback current_distance_travelled (m, from /odom) goes
out once per LiDAR sweep; the result holds total_distance_travelled and the closest object ahead once the robot is
still: closest_object_distance (m) and closest_object_angle (degrees, anticlockwise from straight ahead).

Refused at once, without motion, as aborted with the reason in the status text and the log: fwd_velocity outside
(0, 0.26] m/s, approach_distance outside [0.2, 3.5) m, NaN. Cancelled (or replaced by a new goal): the robot stops
at once and the goal ends preempted with the distance so far. Nothing in range ahead after 3.5 m, still driving
after 60 s, or /odom or /scan silent for 1 s: the robot stops and the goal ends aborted with the reason. The robot
is stopped (zero Twist) whenever a goal ends and when the node shuts down. week5_actions.search_goal holds these
choices; the driving is the Week 4 approach service's (week4_services.approach_drive).
All robot timing is rospy time (sim time under tb3_sim).
"""
import actionlib
import rospy
from tuos_msgs.msg import SearchAction, SearchFeedback, SearchResult

from tb3_client.robot import Robot, RobotError
from week4_services.approach_drive import ApproachDrive
from week5_actions.search_goal import InvalidSearchGoal, outcome_text, plan_search, preempted_text, succeeded, summary

NODE_NAME = "search_action_server"
ACTION_NAME = "/search_action_server"


class SearchServer:
    def __init__(self):
        self.robot = Robot()
        self.drive = None   # the current goal's ApproachDrive (where it started driving)
        self.server = actionlib.SimpleActionServer(ACTION_NAME, SearchAction, self.on_goal, auto_start=False)
        self.server.start()
        rospy.on_shutdown(lambda: self.abort("the action server is shutting down"))
        rospy.loginfo("The '%s' action server is ready to be called...", ACTION_NAME)

    def on_goal(self, goal):
        try:
            plan = plan_search(goal.fwd_velocity, goal.approach_distance)
        except InvalidSearchGoal as error:
            self.abort("Goal refused: {}".format(error))
            return
        self.drive = ApproachDrive(self.robot, plan)
        try:
            with self.robot.exclusive(need_scan=True):
                rospy.loginfo("Searching at %.2f m/s, to stop %.2f m from the object ahead...", plan.velocity,
                              plan.distance)
                outcome = self.drive.run(lambda: rospy.get_rostime().to_sec(),
                                         on_sweep=lambda travelled: self.server.publish_feedback(
                                             SearchFeedback(travelled)),
                                         cancelled=self.server.is_preempt_requested)
                self.robot.stop()
                if outcome is None:
                    result = summary(self.travelled(), None)
                    rospy.logwarn(preempted_text(result))
                    self.server.set_preempted(SearchResult(*result), preempted_text(result))
                    return
                self.robot.wait_until_still()
                self.robot.wait_for_new_sweep()
                result = summary(self.travelled(), self.robot.object_ahead())
        except RobotError as error:
            self.abort("Search failed: {}".format(error), summary(self.travelled(), None))
            return
        self.server.publish_feedback(SearchFeedback(result.total_distance_travelled))
        text = outcome_text(plan, outcome, result)
        if succeeded(outcome):
            rospy.loginfo(text)
            self.server.set_succeeded(SearchResult(*result), text)
        else:
            self.abort(text, result)

    def travelled(self):
        """Metres (straight line) from where this goal started, by /odom; 0 before it started."""
        return 0.0 if self.drive is None else self.drive.travelled()

    def abort(self, text, result=None):
        """End the current goal as aborted with `text` (unless it has ended already: on shutdown the hook and the
        goal's own thread both try)."""
        if self.server.is_active():
            rospy.logwarn(text)
            self.server.set_aborted(SearchResult(*(result or summary(0.0, None))), text)


def main():
    rospy.init_node(NODE_NAME)
    SearchServer()
    rospy.spin()


if __name__ == "__main__":
    main()
