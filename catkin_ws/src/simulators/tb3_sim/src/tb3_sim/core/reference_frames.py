"""Gazebo's `reference_frame` / `relative_entity_name` arguments, in 2D.

"", "world", "map" and "/map" all mean the world frame (Gazebo's own FIXME: "map is really wrong").
Any other name must be a model, given as `model` or scoped as `model::link` (Gazebo wants a link name there;
every tb3_sim model has a single link at its origin, so both spellings mean the model's frame).

Deliberate difference: Gazebo's set_model_state adds a relative pose to the *moved model's own* position (a
known bug); here a pose relative to a frame is composed with that frame's pose, as the field's name says.
"""

import math

from tb3_sim.core.errors import UnknownFrameError
from tb3_sim.core.geometry import Pose2D, Twist2D, wrap_angle
from tb3_sim.core.model_xml import compose

WORLD_FRAME_NAMES = ("", "world", "map", "/map")
SCOPE_SEPARATOR = "::"


def frame_state(world, name):
    """The world.ModelState of the frame `name`, or None for the world frame; raises UnknownFrameError."""
    if name in WORLD_FRAME_NAMES:
        return None
    model_name = name.split(SCOPE_SEPARATOR, 1)[0]
    if not world.has_model(model_name):
        raise UnknownFrameError(f"reference frame '{name}' is not a model (nor '', world, map or /map)")
    return world.get_model_state(model_name)


def to_world(frame, pose, twist):
    """(pose, twist) given in `frame` (a ModelState or None) as world-frame values.

    The twist is rotated into the world frame; the frame's own motion is not added (as Gazebo).
    """
    if frame is None:
        return pose, twist
    return compose(frame.pose, pose), twist.rotated(frame.pose.yaw)


def from_world(frame, pose, twist):
    """World-frame (pose, twist) expressed relative to `frame` (a ModelState or None): the pose in the frame's
    coordinates and the velocity difference rotated into the frame (Gazebo's get_model_state)."""
    if frame is None:
        return pose, twist
    origin = frame.pose
    c, s = math.cos(origin.yaw), math.sin(origin.yaw)
    dx, dy = pose.x - origin.x, pose.y - origin.y
    moving = Twist2D(twist.vx - frame.twist.vx, twist.vy - frame.twist.vy, twist.wz - frame.twist.wz)
    return (Pose2D(c * dx + s * dy, -s * dx + c * dy, wrap_angle(pose.yaw - origin.yaw)),
            moving.rotated(-origin.yaw))
