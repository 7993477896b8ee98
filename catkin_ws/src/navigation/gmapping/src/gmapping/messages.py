"""Conversions between ROS messages and lab_nav.slam's plain values (poses as (x, y, yaw) tuples)."""

import math

from geometry_msgs.msg import Quaternion, TransformStamped

from lab_nav.slam import LaserScanData


def yaw_of(q):
    """Yaw (rad) of a geometry_msgs Quaternion."""
    return math.atan2(2.0 * (q.w * q.z + q.x * q.y), 1.0 - 2.0 * (q.y * q.y + q.z * q.z))


def laser_z_axis(q):
    """The z component of the laser's z axis in the base frame: 1 mounted upwards, -1 upside down."""
    return 1.0 - 2.0 * (q.x * q.x + q.y * q.y)


def pose_of(transform):
    """(x, y, yaw) of a geometry_msgs Transform."""
    return transform.translation.x, transform.translation.y, yaw_of(transform.rotation)


def scan_data(scan, upside_down):
    """LaserScanData of a sensor_msgs/LaserScan; an upside-down laser's angles are mirrored (gmapping does so)."""
    sign = -1.0 if upside_down else 1.0
    return LaserScanData(scan.header.stamp.to_sec(), scan.ranges, sign * scan.angle_min,
                         sign * scan.angle_increment, scan.range_min, scan.range_max)


def transform_message(pose, parent, child, stamp):
    """TransformStamped parent -> child of a 2D pose."""
    message = TransformStamped()
    message.header.frame_id, message.header.stamp, message.child_frame_id = parent, stamp, child
    message.transform.translation.x, message.transform.translation.y = pose[0], pose[1]
    message.transform.rotation = Quaternion(0.0, 0.0, math.sin(pose[2] / 2.0), math.cos(pose[2] / 2.0))
    return message
