#!/usr/bin/env python3
# Part 2 under another file name, registered on the same service name as Part 1 (each part is shown on its own),
# timed in whole seconds, with a bare boolean returned.
import rospy
from com2009_msgs.srv import TimedMovement
from geometry_msgs.msg import Twist

service_name = "move_service"
SPEEDS = {"fwd": (0.1, 0.0), "back": (-0.1, 0.0), "left": (0.0, 0.3), "right": (0.0, -0.3)}

rospy.init_node("timed_move_server")
pub = rospy.Publisher("cmd_vel", Twist, queue_size=10)


def callback_function(service_request):
    if service_request.movement_request not in SPEEDS or service_request.duration <= 0:
        return False
    vel = Twist()
    vel.linear.x, vel.angular.z = SPEEDS[service_request.movement_request]
    start_time = rospy.get_rostime()
    pub.publish(vel)
    while (rospy.get_rostime().secs - start_time.secs) < service_request.duration:
        continue
    pub.publish(Twist())
    return True


srv = rospy.Service(service_name, TimedMovement, callback_function)
rospy.spin()
