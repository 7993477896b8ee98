"""lab_web.packed: a serialised geometry_msgs/PoseArray read with numpy gives the poses genpy would, as float32."""
import base64
import io
import math

import numpy as np
import pytest
from geometry_msgs.msg import Pose, PoseArray

from lab_web.packed import points_base64, unpack_pose_array

POSES = [(1.5, -2.25, 0.3), (-0.125, 4.0, -3.0), (0.0, 0.0, math.pi / 2)]


def serialised(poses, frame_id="map"):
    message = PoseArray()
    message.header.frame_id = frame_id
    for x, y, yaw in poses:
        pose = Pose()
        pose.position.x, pose.position.y = x, y
        pose.orientation.z, pose.orientation.w = math.sin(yaw / 2), math.cos(yaw / 2)
        message.poses.append(pose)
    buffer = io.BytesIO()
    message.serialize(buffer)
    return buffer.getvalue()


def test_the_poses_are_x_y_yaw_in_float32_and_their_base64_reads_back():
    packed = unpack_pose_array(serialised(POSES), 10)
    assert packed.frame_id == "map" and packed.poses.dtype == np.float32
    assert np.allclose(packed.poses, POSES, atol=1e-6)
    again = np.frombuffer(base64.b64decode(packed.base64()), dtype="<f4").reshape(-1, 3)
    assert again.tolist() == packed.poses.tolist()


def test_only_the_first_max_poses_are_kept_and_an_empty_cloud_is_empty():
    assert np.allclose(unpack_pose_array(serialised(POSES), 2).poses, POSES[:2], atol=1e-6)
    empty = unpack_pose_array(serialised([], "odom"), 10)
    assert empty.frame_id == "odom" and empty.poses.shape == (0, 3) and empty.base64() == ""


@pytest.mark.parametrize("cut, why", [(10, "header"), (18, "frame_id"), (21, "pose count"), (-8, "3 poses in 160")])
def test_bytes_that_do_not_add_up_are_refused_with_what_is_wrong(cut, why):
    with pytest.raises(ValueError, match=why):
        unpack_pose_array(serialised(POSES)[:cut], 10)


def test_points_are_x_y_float32_pairs_and_none_is_empty():
    text = points_base64([[1.5, -2.0], [0.001, 3.25]])
    assert np.frombuffer(base64.b64decode(text), dtype="<f4").tolist() == pytest.approx([1.5, -2.0, 0.001, 3.25])
    assert points_base64([]) == ""
