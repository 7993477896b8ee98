#!/usr/bin/env python3
"""The ROS 2 Services unit's simulation services for tb3_sim: /moving and /stop (std_srvs/Empty).

/moving publishes one Twist (0.3 m/s, 0.3 rad/s) on /cmd_vel, so the robot drives in a circle (the simulated
robot holds the last command); /stop publishes one zero Twist.
"""
import rospy
from geometry_msgs.msg import Twist
from std_srvs.srv import Empty, EmptyResponse

MOVING_LINEAR_MPS = 0.3
MOVING_ANGULAR_RADPS = 0.3


class MovingStopServices:
    def __init__(self):
        self.cmd_vel = rospy.Publisher("/cmd_vel", Twist, queue_size=1)
        self.moving = rospy.Service("/moving", Empty, self.on_moving)
        self.stop = rospy.Service("/stop", Empty, self.on_stop)

    def publish(self, linear, angular):
        twist = Twist()
        twist.linear.x, twist.angular.z = linear, angular
        self.cmd_vel.publish(twist)

    def on_moving(self, request):
        self.publish(MOVING_LINEAR_MPS, MOVING_ANGULAR_RADPS)
        return EmptyResponse()

    def on_stop(self, request):
        self.publish(0.0, 0.0)
        return EmptyResponse()


if __name__ == "__main__":
    rospy.init_node("moving_stop_services")
    MovingStopServices()
    rospy.spin()
