#!/usr/bin/env python3
# Week 4 part 1: when /move_service is called with true, drive forwards at 0.1 m/s for 5 seconds, then stop.
import rospy
from geometry_msgs.msg import Twist
from tuos_msgs.srv import SetBool, SetBoolResponse

rospy.init_node("move_server")
pub = rospy.Publisher("/cmd_vel", Twist, queue_size=10)


def callback_function(request):
    response = SetBoolResponse()
    if request.request_signal:
        vel = Twist()
        vel.linear.x = 0.1
        rate = rospy.Rate(10)
        start_time = rospy.get_time()
        while rospy.get_time() - start_time < 5 and not rospy.is_shutdown():
            pub.publish(vel)
            rate.sleep()
        pub.publish(Twist())
        response.response_signal = True
        response.response_message = "I moved forwards for 5 seconds"
    else:
        response.response_signal = False
        response.response_message = "Nothing to do, send true to move"
    return response


rospy.Service("/move_service", SetBool, callback_function)
rospy.loginfo("the move_service server is ready")
rospy.spin()
