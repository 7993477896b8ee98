"""Shared ROS plumbing of the tf2 tutorial nodes: building TransformStamped messages and waiting politely
for frames that do not exist yet."""
import rospy
import tf2_ros
from geometry_msgs.msg import TransformStamped

from learning_tf2.follow import yaw_quaternion
from stop_request.closed_topic import publish_unless_shut_down

LOOKUP_ERRORS = (tf2_ros.LookupException, tf2_ros.ConnectivityException, tf2_ros.ExtrapolationException)
WAITING_LOG_PERIOD_S = 5.0


def transform(parent, child, x, y, yaw=0.0, stamp=None):
    """A TransformStamped placing `child` at (x, y) with heading `yaw` in `parent`, stamped now by default."""
    message = TransformStamped()
    message.header.stamp = stamp if stamp is not None else rospy.Time.now()
    message.header.frame_id = parent
    message.child_frame_id = child
    message.transform.translation.x, message.transform.translation.y = x, y
    rotation = message.transform.rotation
    rotation.x, rotation.y, rotation.z, rotation.w = yaw_quaternion(yaw)
    return message


def log_waiting(error):
    """One throttled line while frames are missing: normal at start-up, not an error."""
    rospy.loginfo_throttle(WAITING_LOG_PERIOD_S, "Waiting for the frames to exist: {}".format(error))


def broadcast_carrot(offset_at, rate_hz=10):
    """Broadcast turtle1 -> carrot1 at `rate_hz` until shutdown, the carrot at offset_at(now_s) = (x, y) m
    in turtle1's frame."""
    broadcaster = tf2_ros.TransformBroadcaster()
    rate = rospy.Rate(rate_hz)
    while not rospy.is_shutdown():
        now = rospy.Time.now()
        carrot = transform("turtle1", "carrot1", *offset_at(now.to_sec()), stamp=now)
        if not publish_unless_shut_down(broadcaster.sendTransform, carrot):
            break
        try:
            rate.sleep()
        except rospy.ROSInterruptException:
            break
