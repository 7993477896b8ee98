"""Conversions to ROS messages: exact stamps, quaternions, Gazebo's frames and fields."""
import math

import numpy as np
import pytest
from geometry_msgs.msg import Pose

from tb3_sim.core.geometry import Pose2D, Twist2D
from tb3_sim.core.lidar import ScanResult
from tb3_sim.core.turtlebot3 import WAFFLE
from tb3_sim.ros import messages


def test_stamps_of_5_ms_steps_are_exact():
    stamp = messages.stamp(12345 * 0.005)
    assert (stamp.secs, stamp.nsecs) == (61, 725000000)


def test_pose_round_trip_and_zero_quaternion():
    pose = Pose2D(1.0, -2.0, 2.5)
    assert messages.pose_from_message(messages.pose_message(pose)) == pytest.approx(pose)
    assert messages.pose_from_message(Pose()).yaw == 0.0


def test_rpy_to_quaternion_matches_a_pure_roll_and_a_pure_yaw():
    assert messages.rpy_to_quaternion(-1.57, 0.0, 0.0) == pytest.approx(
        (math.sin(-0.785), 0.0, 0.0, math.cos(-0.785)))
    assert messages.rpy_to_quaternion(0.0, 0.0, 1.0) == pytest.approx((0.0, 0.0, math.sin(0.5), math.cos(0.5)))


def test_odometry_twist_is_the_given_body_twist():
    odom = messages.odometry_message(1.0, Pose2D(1.0, 2.0, 0.5), Twist2D(0.2, 0.01, 0.3))
    assert (odom.twist.twist.linear.x, odom.twist.twist.linear.y, odom.twist.twist.angular.z) == (0.2, 0.01, 0.3)
    assert odom.pose.covariance[35] == 1e-3


def test_static_tf_has_one_transform_per_fixed_joint():
    message = messages.static_tf_message(0.0, WAFFLE.static_transforms)
    assert [(t.header.frame_id, t.child_frame_id) for t in message.transforms] == [
        (parent, child) for parent, child, _, _ in WAFFLE.static_transforms]


def test_scan_message_keeps_inf_and_fills_zero_intensities():
    ranges = np.full(360, np.inf, dtype=np.float32)
    ranges[0] = 1.25
    scan = messages.scan_message(ScanResult(ranges, 2.0))
    assert scan.ranges[0] == 1.25 and math.isinf(scan.ranges[1])
    assert scan.intensities == [0.0] * 360
    assert scan.header.frame_id == "base_scan"
