#!/usr/bin/env python3
"""Exercise 4.2: the /moving_right server (std_srvs/SetBool).

data true: the robot moves forwards while turning right (0.3 m/s, -0.3 rad/s), success True.
data false: the robot stops, success False, as the course's solution answers.
"""
import rospy
from std_srvs.srv import SetBool, SetBoolResponse

from tb3_client.robot import Robot

LINEAR_MPS = 0.3
ANGULAR_RADPS = -0.3


class MovingRightServer:
    def __init__(self):
        self.robot = Robot()
        self.service = rospy.Service("/moving_right", SetBool, self.callback)

    def callback(self, request):
        if request.data:
            self.robot.drive(LINEAR_MPS, ANGULAR_RADPS)
            return SetBoolResponse(True, "MOVING TO THE RIGHT RIGHT RIGHT!")
        self.robot.stop()
        return SetBoolResponse(False, "It is time to stop!")


if __name__ == "__main__":
    rospy.init_node("moving_right_server")
    MovingRightServer()
    rospy.spin()
