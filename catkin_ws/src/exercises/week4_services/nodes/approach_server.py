#!/usr/bin/env python3
"""Week 4, part 4: the /approach_service server (tuos_msgs/Approach).

Drives forwards at approach_velocity until the closest object ahead (LiDAR arc of +-20 degrees around
straight ahead) is approach_distance away, stops, and replies with the distance the LiDAR measures once the
robot is still. Refused with a clear message and no motion: velocity outside (0, 0.26] m/s, distance outside
[0.2, 3.5) m, NaN, or a second request while one is running (requests are never interleaved).
Nothing ahead: drives at most 3.5 m (the LiDAR's range) and says so. Still driving after 60 s (a valid but
tiny velocity, or the robot blocked by something too low for the LiDAR): stops and says so. /odom or /scan
silent for 1 s (the simulator died): stops and replies with the failure.
"""
import rospy
from tuos_msgs.srv import Approach, ApproachResponse

from tb3_client.robot import Robot, RobotError
from week4_services.approach import TIME_LIMIT_S, Outcome
from week4_services.approach_drive import ApproachDrive
from week4_services.requests import InvalidRequest, approach

NODE_NAME = "approach_service_server"
SERVICE_NAME = "approach_service"


class ApproachServer:
    def __init__(self):
        self.robot = Robot()
        self.service = rospy.Service(SERVICE_NAME, Approach, self.callback)
        rospy.loginfo("The '%s' service is ready to be called...", SERVICE_NAME)

    def callback(self, request):
        try:
            plan = approach(request.approach_distance, request.approach_velocity)
            with self.robot.exclusive(need_scan=True):
                outcome = self.drive_until_close(plan)
                self.robot.stop()
                self.robot.wait_until_still()
                self.robot.wait_for_new_sweep()
                final = self.robot.object_ahead()
        except (InvalidRequest, RobotError) as error:
            rospy.logerr("Request refused: %s", error)
            return ApproachResponse("Request failed: {}".format(error))
        message = self.describe(plan, outcome, final)
        rospy.loginfo(message)
        return ApproachResponse(message)

    def drive_until_close(self, plan):
        """Approach under the shared drive loop (week4_services.approach_drive); returns the outcome."""
        rospy.loginfo("Approaching at %.2f m/s to stop %.2f m from the object ahead...",
                      plan.velocity, plan.distance)
        return ApproachDrive(self.robot, plan).run(lambda: rospy.get_rostime().to_sec())

    @staticmethod
    def describe(plan, outcome, final):
        seen = "the LiDAR sees nothing ahead" if final is None else \
            "the closest object ahead is {:.3f} m away".format(final.distance)
        if outcome is Outcome.ARRIVED:
            return "Stopped: {} (requested {:.2f} m).".format(seen, plan.distance)
        if outcome is Outcome.ALREADY_THERE:
            return "Did not move: {}, already within the requested {:.2f} m.".format(seen, plan.distance)
        if outcome is Outcome.TIME_LIMIT:
            return "Stopped after the {:.0f} s time limit: {} (requested {:.2f} m).".format(
                TIME_LIMIT_S, seen, plan.distance)
        return "Stopped after the 3.5 m safety limit with no object in range ahead: {}.".format(seen)


def main():
    rospy.init_node(NODE_NAME)
    ApproachServer()
    rospy.spin()


if __name__ == "__main__":
    main()
