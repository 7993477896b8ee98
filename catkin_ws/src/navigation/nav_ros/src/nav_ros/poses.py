"""2D poses (x, y, yaw) between ROS messages and plain tuples, and their composition (SE(2))."""
import math

from geometry_msgs.msg import Pose, Quaternion, TransformStamped

from lab_nav.angles import yaw_of_quaternion


def quaternion(yaw):
    return Quaternion(0.0, 0.0, math.sin(yaw / 2.0), math.cos(yaw / 2.0))


def from_pose(pose):
    """(x, y, yaw) of a geometry_msgs/Pose."""
    q = pose.orientation
    return (pose.position.x, pose.position.y, yaw_of_quaternion(q.x, q.y, q.z, q.w))


def from_transform(transform):
    """(x, y, yaw) of a geometry_msgs/Transform (or TransformStamped)."""
    t = getattr(transform, "transform", transform)
    q = t.rotation
    return (t.translation.x, t.translation.y, yaw_of_quaternion(q.x, q.y, q.z, q.w))


def to_pose(xy_yaw):
    pose = Pose()
    pose.position.x, pose.position.y = xy_yaw[0], xy_yaw[1]
    pose.orientation = quaternion(xy_yaw[2])
    return pose


def to_transform(xy_yaw, parent, child, stamp):
    message = TransformStamped()
    message.header.frame_id, message.child_frame_id, message.header.stamp = parent, child, stamp
    message.transform.translation.x, message.transform.translation.y = xy_yaw[0], xy_yaw[1]
    message.transform.rotation = quaternion(xy_yaw[2])
    return message


def compose(a, b):
    """The pose b expressed in a's parent frame (a then b)."""
    c, s = math.cos(a[2]), math.sin(a[2])
    return (a[0] + c * b[0] - s * b[1], a[1] + s * b[0] + c * b[1], math.atan2(math.sin(a[2] + b[2]),
                                                                                 math.cos(a[2] + b[2])))


def inverse(a):
    c, s = math.cos(a[2]), math.sin(a[2])
    return (-c * a[0] - s * a[1], s * a[0] - c * a[1], -a[2])
