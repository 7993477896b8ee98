#!/usr/bin/env python3
# Week 4 part 4: /approach_service drives towards the object ahead and stops approach_distance away from it.
import math

import rospy
from geometry_msgs.msg import Twist
from sensor_msgs.msg import LaserScan
from tuos_msgs.srv import Approach, ApproachResponse

MAX_SPEED = 0.26       # the Waffle's top speed (m/s)
MIN_DISTANCE = 0.2     # the LiDAR cannot see closer than this (m)
MAX_DISTANCE = 3.5     # the LiDAR's range (m)
TIME_LIMIT = 60        # never drive longer than this (s)

rospy.init_node("approach_server")
pub = rospy.Publisher("/cmd_vel", Twist, queue_size=10)
latest_scan = None


def scan_callback(scan):
    global latest_scan
    latest_scan = scan


def distance_ahead(scan):
    # the closest reading within 20 degrees of straight ahead
    closest = math.inf
    for i, distance in enumerate(scan.ranges):
        angle = scan.angle_min + i * scan.angle_increment
        angle = math.atan2(math.sin(angle), math.cos(angle))
        if abs(angle) <= math.radians(20) and scan.range_min <= distance <= scan.range_max:
            closest = min(closest, distance)
    return closest


def wait_for_new_scan(old_scan):
    while latest_scan is old_scan and not rospy.is_shutdown():
        rospy.sleep(0.01)
    return latest_scan


def callback_function(request):
    distance, speed = request.approach_distance, request.approach_velocity
    # written so that NaN fails too
    if not (0 < speed <= MAX_SPEED and MIN_DISTANCE <= distance < MAX_DISTANCE):
        return ApproachResponse("Invalid request: speed must be in (0, 0.26] m/s and distance in [0.2, 3.5) m")
    vel = Twist()
    vel.linear.x = speed
    scan = wait_for_new_scan(latest_scan)
    start_time = rospy.get_time()
    while distance_ahead(scan) > distance and rospy.get_time() - start_time < TIME_LIMIT:
        pub.publish(vel)
        scan = wait_for_new_scan(scan)
    pub.publish(Twist())
    rospy.sleep(1)
    scan = wait_for_new_scan(latest_scan)
    return ApproachResponse("Stopped {:.2f} m from the object ahead".format(distance_ahead(scan)))


rospy.Subscriber("/scan", LaserScan, scan_callback)
rospy.Service("/approach_service", Approach, callback_function)
rospy.loginfo("the approach_service server is ready")
rospy.spin()
