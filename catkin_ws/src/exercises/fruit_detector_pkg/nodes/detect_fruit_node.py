#!/usr/bin/env python3
"""The ROS 2 "Services" unit's fruit detector, ported to ROS 1: one node that subscribes, serves and publishes.

Subscribes   /camera/rgb/image_raw (sensor_msgs/Image, the TurtleBot3 Waffle's RGB camera); keeps only the latest
             frame: nothing is computed per frame, so the node's CPU goes to rospy receiving the images (about
             40 % of a core for 1920x1080 rgb8 at 30 Hz, 7 % for 640x480). Detection runs on request only.
Serves       /detect_fruit_service (custom_interfaces/StringServiceMessage): `detect` "apple" or "banana" (any
             case, spaces trimmed). success True iff that fruit is in view in the latest frame, with a message
             "apple detected at x=..., y=... (...), in view"; "no apple in view" otherwise. An unknown word, no
             image yet, or an image more than 2 s old answers success False with the reason.
Publishes    image_detected_fruit (sensor_msgs/Image, bgr8, the camera's size and header): the frame each
             answered request looked at, with the fruit boxed and labelled (to watch it with a display:
             rosrun image_view image_view image:=/image_detected_fruit).
Colour thresholds and the minimum blob size are documented in fruit_detector_pkg.fruit_detection.
"""
import time

import rospy
from custom_interfaces.srv import StringServiceMessage, StringServiceMessageResponse
from cv_bridge import CvBridge, CvBridgeError
from sensor_msgs.msg import Image

from fruit_detector_pkg.fruit_detection import annotate, detect_fruit
from fruit_detector_pkg.fruit_request import FruitRequestError, check_image_age, fruit_from_request, reply_for

NODE_NAME = "detect_fruit_node"
CAMERA_TOPIC = "/camera/rgb/image_raw"
SERVICE_NAME = "/detect_fruit_service"
ANNOTATED_TOPIC = "image_detected_fruit"
IMAGE_BUFFER_BYTES = 2 ** 25   # room for a whole 1920x1080 rgb8 frame (6 MB), so rospy never lags behind


class DetectFruitNode:
    def __init__(self):
        self.bridge = CvBridge()
        self.latest = None   # (Image message, time.monotonic() of its arrival)
        self.subscriber = rospy.Subscriber(CAMERA_TOPIC, Image, self.on_image, queue_size=1,
                                           buff_size=IMAGE_BUFFER_BYTES)
        self.publisher = rospy.Publisher(ANNOTATED_TOPIC, Image, queue_size=1)
        self.service = rospy.Service(SERVICE_NAME, StringServiceMessage, self.on_request)
        rospy.loginfo("The '%s' service is ready: ask for an apple or a banana.", SERVICE_NAME)

    def on_image(self, image):
        self.latest = (image, time.monotonic())

    def on_request(self, request):
        latest = self.latest
        try:
            fruit = fruit_from_request(request.detect)
            check_image_age(CAMERA_TOPIC, None if latest is None else time.monotonic() - latest[1])
            frame = self.bridge.imgmsg_to_cv2(latest[0], desired_encoding="bgr8")
        except (FruitRequestError, CvBridgeError) as error:
            rospy.logwarn("Request failed: %s", error)
            return StringServiceMessageResponse(False, str(error))
        detection = detect_fruit(frame, fruit)
        self.publisher.publish(self.bridge.cv2_to_imgmsg(annotate(frame, detection), "bgr8", latest[0].header))
        reply = reply_for(detection)
        rospy.loginfo(reply.message)
        return StringServiceMessageResponse(reply.success, reply.message)


def main():
    rospy.init_node(NODE_NAME)
    DetectFruitNode()
    rospy.spin()


if __name__ == "__main__":
    main()
