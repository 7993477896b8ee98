#!/usr/bin/env python3
"""The quiz's /turn server (services_quiz_srv/Turn): spin right or left at angular_velocity for `time`
seconds, stop, and reply success True. Bad requests get success False and no motion."""
import rospy
from services_quiz_srv.srv import Turn, TurnResponse

from services_quiz.turn import InvalidRequest, turn_motion
from tb3_client.robot import Robot, RobotError


class TurnServer:
    def __init__(self):
        self.robot = Robot()
        self.service = rospy.Service("/turn", Turn, self.callback)

    def callback(self, request):
        try:
            motion = turn_motion(request.direction, request.angular_velocity, request.time)
            self.robot.perform(motion, "Turning {} at {:.2f} rad/s for {} s".format(
                request.direction, request.angular_velocity, request.time))
        except (InvalidRequest, RobotError) as error:
            rospy.logwarn("Refused: %s", error)
            return TurnResponse(False)
        return TurnResponse(True)


if __name__ == "__main__":
    rospy.init_node("turn_server")
    TurnServer()
    rospy.spin()
