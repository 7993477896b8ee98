"""gmapping's message conversions: TF and laser mounting maths (the map message: tests/unit/nav_ros)."""
import math

import pytest
import rospy
from geometry_msgs.msg import Quaternion
from sensor_msgs.msg import LaserScan

from gmapping import messages


def test_a_transform_message_carries_the_pose_as_a_yaw_quaternion():
    message = messages.transform_message((1.0, -2.0, 0.5), "map", "odom", rospy.Time(3))
    assert messages.pose_of(message.transform) == pytest.approx((1.0, -2.0, 0.5))
    assert (message.header.frame_id, message.child_frame_id) == ("map", "odom")


@pytest.mark.parametrize("quaternion, z_axis", [
    (Quaternion(0, 0, 0, 1), 1.0),                                      # upright
    (Quaternion(1, 0, 0, 0), -1.0),                                     # rolled over: upside down
    (Quaternion(0, math.sin(0.1), 0, math.cos(0.1)), math.cos(0.2)),    # pitched 0.2 rad: not planar
])
def test_laser_z_axis(quaternion, z_axis):
    assert messages.laser_z_axis(quaternion) == pytest.approx(z_axis)


def test_an_upside_down_laser_has_its_angles_mirrored():
    scan = LaserScan(angle_min=0.1, angle_increment=0.02, range_min=0.12, range_max=3.5, ranges=[1.0, 2.0])
    scan.header.stamp = rospy.Time(4, 500000000)
    data = messages.scan_data(scan, upside_down=True)
    assert (data.stamp, data.angle_min, data.angle_increment) == (4.5, -0.1, -0.02)
