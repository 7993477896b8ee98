#!/usr/bin/env python3
# Part 1, as the course's template has it: a publisher at module level, whole seconds of ROS time, a bare tuple
# returned instead of a SetBoolResponse, and the older message package.
import rospy
from geometry_msgs.msg import Twist
from tuos_ros_msgs.srv import SetBool

service_name = "move_service"

rospy.init_node(f"{service_name}_server")
pub = rospy.Publisher("cmd_vel", Twist, queue_size=10)


def callback_function(service_request):
    vel = Twist()
    if service_request.request_signal:
        print("Request received (a 'true' instruction), moving forwards for 5 seconds...")
        start_time = rospy.get_rostime()
        vel.linear.x = 0.1
        pub.publish(vel)
        print("Moving the robot forwards...")
        while (rospy.get_rostime().secs - start_time.secs) < 5:
            continue
        print("5 seconds have passed, stopping the robot...")
        vel.linear.x = 0.0
        pub.publish(vel)
        return True, "Request complete."
    print("Request received (a 'false' instruction): doing nothing.")
    return False, "Nothing happened, set request_signal to 'true' next time."


srv = rospy.Service(service_name, SetBool, callback_function)
rospy.loginfo(f"the '{service_name}' Server is ready to be called...")
rospy.spin()
