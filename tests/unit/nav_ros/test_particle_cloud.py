"""amcl's /particlecloud message: the bytes rospy sends decode as the PoseArray of the particles."""
import io
import math

import numpy as np
import pytest
import rospy
from geometry_msgs.msg import PoseArray
from nav_ros import poses
from nav_ros.particle_cloud import ParticleCloud
from rospy.msg import serialize_message


def _wire(message, seq=7):
    """What rospy writes for the message, after the 4-byte length."""
    buff = io.BytesIO()
    serialize_message(buff, seq, message)
    return buff.getvalue()[4:]


def _sent(message):
    """The message as a subscriber decodes it."""
    return PoseArray().deserialize(_wire(message))


def test_the_wire_form_is_the_pose_array_of_the_particles():
    particles = np.array([[1.0, -2.0, 0.0], [0.5, 0.25, math.pi / 2], [-3.0, 4.0, -math.pi]])
    received = _sent(ParticleCloud(particles, "map", rospy.Time(12, 345)))
    assert (received.header.seq, received.header.frame_id) == (7, "map")
    assert (received.header.stamp.secs, received.header.stamp.nsecs) == (12, 345)
    assert len(received.poses) == 3
    for pose, (x, y, yaw) in zip(received.poses, particles):
        assert (pose.position.x, pose.position.y, pose.position.z) == (x, y, 0.0)
        q = pose.orientation
        assert (q.x, q.y) == (0.0, 0.0)
        assert (q.z, q.w) == pytest.approx((math.sin(yaw / 2), math.cos(yaw / 2)))


def test_the_same_bytes_as_a_genpy_pose_array():
    particles = np.random.default_rng(0).uniform(-5, 5, (50, 3))
    plain = PoseArray()
    plain.header.frame_id, plain.header.stamp = "map", rospy.Time(1, 2)
    plain.poses = [poses.to_pose(p) for p in particles]
    assert _wire(ParticleCloud(particles, "map", rospy.Time(1, 2))) == _wire(plain)


def test_an_empty_cloud():
    assert _sent(ParticleCloud(np.zeros((0, 3)), "map", rospy.Time(0))).poses == []
