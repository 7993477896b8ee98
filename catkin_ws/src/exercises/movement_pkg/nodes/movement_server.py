#!/usr/bin/env python3
"""The /movement server (custom_interfaces/MyCustomServiceMessage): "Turn Right", "Turn Left" or "Stop".

The robot keeps the new velocity after the reply; any other word gets success False and no motion.
"""
import rospy
from custom_interfaces.srv import MyCustomServiceMessage, MyCustomServiceMessageResponse

from movement_pkg.moves import InvalidRequest, movement_velocity
from tb3_client.robot import Robot


class MovementServer:
    def __init__(self):
        self.robot = Robot()
        self.service = rospy.Service("/movement", MyCustomServiceMessage, self.callback)

    def callback(self, request):
        try:
            linear, angular = movement_velocity(request.move)
        except InvalidRequest as error:
            rospy.logwarn("Refused: %s", error)
            return MyCustomServiceMessageResponse(False)
        self.robot.drive(linear, angular)
        rospy.loginfo("%s", request.move)
        return MyCustomServiceMessageResponse(True)


if __name__ == "__main__":
    rospy.init_node("movement_server")
    MovementServer()
    rospy.spin()
