#!/usr/bin/env python3
# The velocity helper the course's nodes import (`from tb3 import Tb3Move`), next to them in src/.
import rospy
from geometry_msgs.msg import Twist


class Tb3Move():
    def __init__(self):
        self.publisher = rospy.Publisher("cmd_vel", Twist, queue_size=10)
        self.vel_cmd = Twist()

    def set_move_cmd(self, linear=0.0, angular=0.0):
        self.vel_cmd.linear.x = linear
        self.vel_cmd.angular.z = angular

    def publish(self):
        self.publisher.publish(self.vel_cmd)

    def stop(self):
        self.set_move_cmd()
        self.publish()
