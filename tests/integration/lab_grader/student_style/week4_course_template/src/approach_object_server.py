#!/usr/bin/env python3
# Part 3 under another file name: approach the object ahead with the older message package, a bare string returned.
# It refuses speeds and distances that are not positive (NaN too), but not a speed above the robot's maximum.
import rospy
from com2009_msgs.srv import Approach
from geometry_msgs.msg import Twist
from sensor_msgs.msg import LaserScan

rospy.init_node("approach_server")
pub = rospy.Publisher("cmd_vel", Twist, queue_size=10)
front = [float("inf")]


def scan_callback(scan):
    ahead = [r for r in scan.ranges[:21] + scan.ranges[-20:] if scan.range_min <= r <= scan.range_max]
    front[0] = min(ahead) if ahead else float("inf")


def callback_function(service_request):
    distance, speed = service_request.approach_distance, service_request.approach_velocity
    if not (speed > 0 and 0.2 <= distance < 3.5):
        return "Invalid request."
    vel = Twist()
    vel.linear.x = speed
    rate = rospy.Rate(10)
    start_time = rospy.get_rostime()
    while front[0] > distance and (rospy.get_rostime().secs - start_time.secs) < 30:
        pub.publish(vel)
        rate.sleep()
    pub.publish(Twist())
    return f"Stopped: the object ahead is {front[0]:.2f} m away."


rospy.Subscriber("scan", LaserScan, scan_callback)
srv = rospy.Service("approach_service", Approach, callback_function)
rospy.spin()
