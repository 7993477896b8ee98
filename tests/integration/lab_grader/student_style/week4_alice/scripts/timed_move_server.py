#!/usr/bin/env python3
# Week 4 part 3: /timed_move_service drives (fwd, back) or turns (left, right) for a number of seconds.
import rospy
from geometry_msgs.msg import Twist
from tuos_msgs.srv import TimedMovement, TimedMovementResponse

# linear (m/s) and angular (rad/s) velocity for each movement
SPEEDS = {"fwd": (0.1, 0.0), "back": (-0.1, 0.0), "left": (0.0, 0.3), "right": (0.0, -0.3)}

rospy.init_node("timed_move_server")
pub = rospy.Publisher("/cmd_vel", Twist, queue_size=10)


def callback_function(request):
    if request.movement_request not in SPEEDS or request.duration <= 0:
        rospy.logwarn("I cannot do '%s' for %d seconds", request.movement_request, request.duration)
        return TimedMovementResponse(False)
    vel = Twist()
    vel.linear.x, vel.angular.z = SPEEDS[request.movement_request]
    rate = rospy.Rate(10)
    start_time = rospy.get_time()
    while rospy.get_time() - start_time < request.duration and not rospy.is_shutdown():
        pub.publish(vel)
        rate.sleep()
    pub.publish(Twist())
    return TimedMovementResponse(True)


rospy.Service("/timed_move_service", TimedMovement, callback_function)
rospy.loginfo("the timed_move_service server is ready")
rospy.spin()
