#!/usr/bin/env python3
"""The my_service service (beginner_tutorials/gazebo_server): the LiDAR distance at a bearing.

Keeps the latest /scan (sensor_msgs/LaserScan) and answers `distance` = ranges[direction], direction in
degrees counter-clockwise from ahead (0..359 on the TurtleBot3). Before the first scan, and for a direction
the scan does not have, the call fails with a ServiceException saying why; the server keeps serving.
"""
import rospy
from sensor_msgs.msg import LaserScan

from beginner_tutorials.errors import ScanLookupError
from beginner_tutorials.scan_lookup import SCAN_TOPIC, range_at
from beginner_tutorials.srv import gazebo_server, gazebo_serverResponse


class ScanServer:
    def __init__(self):
        self.latest_ranges = None
        self.subscriber = rospy.Subscriber(SCAN_TOPIC, LaserScan, self.on_scan, queue_size=1)
        self.service = rospy.Service("my_service", gazebo_server, self.handle_request)

    def on_scan(self, scan):
        self.latest_ranges = scan.ranges

    def handle_request(self, request):
        try:
            distance = range_at(self.latest_ranges, request.direction)
        except ScanLookupError as error:
            raise rospy.ServiceException(str(error)) from None
        return gazebo_serverResponse(distance=distance)


def main():
    rospy.init_node("scan_server")
    ScanServer()
    rospy.loginfo("my_service is ready: the /scan range at a direction in degrees")
    rospy.spin()


if __name__ == "__main__":
    main()
