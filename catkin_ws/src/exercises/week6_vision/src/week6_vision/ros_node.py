"""The ROS plumbing the Part 6 nodes share (the only module here that imports rospy): the camera subscription,
frames as OpenCV BGR images, Twist commands, and running a node class until Ctrl-C with the robot stopped."""
import rospy
from cv_bridge import CvBridge, CvBridgeError
from geometry_msgs.msg import Twist
from sensor_msgs.msg import Image

from week6_vision.colour_masks import UnknownColour

CAMERA_TOPIC = "/camera/rgb/image_raw"
IMAGE_BUFFER_BYTES = 2 ** 25  # room for a whole 1920x1080 rgb8 frame, so rospy never lags behind
_BRIDGE = CvBridge()


def subscribe_camera(callback):
    """Call `callback(message)` with the newest frame of the robot's camera (older ones are dropped)."""
    return rospy.Subscriber(CAMERA_TOPIC, Image, callback, queue_size=1, buff_size=IMAGE_BUFFER_BYTES)


def bgr_image(message):
    """The frame as a BGR numpy image, or None (with a warning at most every 5 s) if it cannot be read."""
    try:
        return _BRIDGE.imgmsg_to_cv2(message, desired_encoding="bgr8")
    except CvBridgeError as error:
        rospy.logwarn_throttle(5, f"Cannot read the camera image: {error}")
        return None


def velocity_publisher():
    """/cmd_vel, with a zero Twist sent on shutdown (Ctrl-C) so the robot never keeps moving."""
    publisher = rospy.Publisher("/cmd_vel", Twist, queue_size=1)
    rospy.on_shutdown(lambda: publisher.publish(Twist()))
    return publisher


def twist(linear=0.0, angular=0.0):
    message = Twist()
    message.linear.x, message.angular.z = linear, angular
    return message


def run(node_name, node_class):
    """Start the node `node_name`, build `node_class()` (an unknown colour parameter is logged, not raised) and
    spin until shutdown."""
    rospy.init_node(node_name)
    try:
        node_class()
    except UnknownColour as error:
        rospy.logerr(str(error))
        return
    rospy.spin()
