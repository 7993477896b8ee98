#!/usr/bin/env python3
"""Week 4, part 1: the /move_service server (tuos_msgs/SetBool).

request_signal true: drive forwards at 0.1 m/s for 5 s (rospy time), stop, reply True.
request_signal false: do nothing and reply False, telling the caller to send true.
"""
import rospy
from tuos_msgs.srv import SetBool, SetBoolResponse

from tb3_client.robot import Robot, RobotError

NODE_NAME = "move_service_server"
SERVICE_NAME = "move_service"
FORWARD_SPEED_MPS = 0.1
MOVE_DURATION_S = 5.0


class MoveServer:
    def __init__(self):
        self.robot = Robot()
        self.service = rospy.Service(SERVICE_NAME, SetBool, self.callback)
        rospy.loginfo("The '%s' service is ready to be called...", SERVICE_NAME)

    def callback(self, request):
        if not request.request_signal:
            rospy.logwarn("Received a 'false' request: nothing to do.")
            return SetBoolResponse(False, "Nothing happened: set request_signal to 'true' to move the robot.")
        try:
            with self.robot.exclusive():
                start_time = rospy.get_rostime()
                rospy.loginfo("Received a 'true' request: moving forwards for %.0f seconds...", MOVE_DURATION_S)
                self.robot.drive(FORWARD_SPEED_MPS, 0.0)
                self.robot.wait(MOVE_DURATION_S)
        except RobotError as error:
            rospy.logerr("Request failed: %s", error)
            return SetBoolResponse(False, "Request failed: {}".format(error))
        elapsed = (rospy.get_rostime() - start_time).to_sec()
        rospy.loginfo("Request complete: moved for %.1f seconds.", elapsed)
        return SetBoolResponse(True, "Request complete: the robot moved forwards for {:.1f} seconds.".format(elapsed))


def main():
    rospy.init_node(NODE_NAME)
    MoveServer()
    rospy.spin()


if __name__ == "__main__":
    main()
