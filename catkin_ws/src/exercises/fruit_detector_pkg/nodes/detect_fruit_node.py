#!/usr/bin/env python3
"""One node that subscribes, serves and publishes: it keeps the latest /scan, serves /detect_fruit_service
(custom_interfaces/StringServiceMessage) and publishes each answer on /fruit_detection (std_msgs/String)."""
import rospy
from custom_interfaces.srv import StringServiceMessage, StringServiceMessageResponse
from sensor_msgs.msg import LaserScan
from std_msgs.msg import String

from fruit_detector_pkg.fruit_report import fruit_report
from tb3_client.scan_ahead import closest_ahead


class DetectFruitNode:
    def __init__(self):
        self.latest_scan = None
        self.subscriber = rospy.Subscriber("/scan", LaserScan, self.on_scan, queue_size=1)
        self.publisher = rospy.Publisher("/fruit_detection", String, queue_size=10)
        self.service = rospy.Service("/detect_fruit_service", StringServiceMessage, self.on_request)

    def on_scan(self, scan):
        self.latest_scan = scan

    def on_request(self, request):
        scan = self.latest_scan
        ahead = closest_ahead(scan.ranges, scan.angle_min, scan.angle_increment, scan.range_min) if scan else None
        report = fruit_report(request.detect, ahead, scan is not None)
        self.publisher.publish(String(report.message))
        rospy.loginfo(report.message)
        return StringServiceMessageResponse(report.success, report.message)


if __name__ == "__main__":
    rospy.init_node("detect_fruit_node")
    DetectFruitNode()
    rospy.spin()
