#!/usr/bin/env python3
"""The /move server (custom_interfaces/Move): drive forward/backward or turn left/right at `velocity` for
`time` seconds, then stop and reply success True; "stop" stops at once. A bad direction, a speed outside
(0, 0.26] m/s or (0, 1.82] rad/s, or a time outside 1..60 s gets success False and no motion."""
import rospy
from custom_interfaces.srv import Move, MoveResponse

from movement_pkg.moves import InvalidRequest, move_motion
from tb3_client.robot import Robot, RobotError


class MoveServer:
    def __init__(self):
        self.robot = Robot()
        self.service = rospy.Service("/move", Move, self.callback)

    def callback(self, request):
        try:
            self.robot.perform(move_motion(request.direction, request.velocity, request.time))
        except (InvalidRequest, RobotError) as error:
            rospy.logwarn("Refused: %s", error)
            return MoveResponse(False)
        return MoveResponse(True)


if __name__ == "__main__":
    rospy.init_node("move_server")
    MoveServer()
    rospy.spin()
