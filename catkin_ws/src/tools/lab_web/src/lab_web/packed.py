"""Points and poses as the page receives them in bulk: base64 of little-endian float32 values (the page reads them
as one Float32Array). geometry_msgs/PoseArray's serialised bytes are read with numpy, straight to (x, y, yaw) per
pose; a LiDAR sweep's hits are (x, y) per hit. No ROS import (the panel's message class hands over the bytes).

amcl's cloud holds thousands of poses: genpy builds five Python objects per pose and the page's JSON wrote three
floats as text per pose, together most of lab_web's CPU with navigation shown. Here one numpy read, one base64 text
(16 characters a pose), and JSON copies the text as it is. The same for the 360 hits of a sweep, which go out with
every state frame (25 a second) while the sweep changes at 5 Hz: encoded once per sweep, not once per frame.

The ROS 1 wire format (little-endian): Header (uint32 seq, uint32 secs, uint32 nsecs, uint32 length + frame_id
bytes), uint32 count, then per pose position x, y, z and orientation x, y, z, w as float64 (56 bytes).
"""
import base64
import struct

import numpy as np

POSE_FLOAT64S = 7
HEADER_FIXED_BYTES = 12
"""seq, secs, nsecs before frame_id's length."""


class PackedPoses:
    """The frame_id and an (n, 3) float32 array of x (m), y (m), yaw (rad) of a PoseArray's first poses."""

    __slots__ = ("frame_id", "poses")

    def __init__(self, frame_id, poses):
        self.frame_id, self.poses = frame_id, poses

    def base64(self):
        """The poses as base64 of little-endian float32 x, y, yaw, pose after pose."""
        return base64.b64encode(self.poses.astype("<f4", copy=False).tobytes()).decode()


def points_base64(points):
    """Base64 of [[x, y], ...] as little-endian float32 x, y, point after point ("" for none)."""
    return base64.b64encode(np.asarray(points, dtype="<f4").tobytes()).decode()


def _uint32(data, at, what):
    if at + 4 > len(data):
        raise ValueError("the PoseArray ends inside its {} ({} bytes)".format(what, len(data)))
    return struct.unpack_from("<I", data, at)[0]


def unpack_pose_array(data, max_poses):
    """PackedPoses of serialised geometry_msgs/PoseArray `data` (bytes or memoryview), at most `max_poses` of them.
    The yaw is that of a rotation about z (2 atan2(qz, qw)), as the page draws poses in the plane.
    Raises ValueError for bytes that do not add up."""
    length = _uint32(data, HEADER_FIXED_BYTES, "header")
    at = HEADER_FIXED_BYTES + 4
    if at + length > len(data):
        raise ValueError("the PoseArray ends inside its frame_id ({} bytes)".format(len(data)))
    frame_id = bytes(data[at:at + length]).decode("utf-8", "replace")
    at += length
    count = _uint32(data, at, "pose count")
    at += 4
    if at + count * POSE_FLOAT64S * 8 != len(data):
        raise ValueError("the PoseArray says {} poses in {} bytes of poses".format(count, len(data) - at))
    kept = min(count, max_poses)
    values = np.frombuffer(data, dtype="<f8", count=kept * POSE_FLOAT64S, offset=at).reshape(kept, POSE_FLOAT64S)
    poses = np.empty((kept, 3), dtype=np.float32)
    poses[:, 0], poses[:, 1] = values[:, 0], values[:, 1]
    poses[:, 2] = 2.0 * np.arctan2(values[:, 5], values[:, 6])
    return PackedPoses(frame_id, poses)
