"""Helpers shared by the robot and the models: reading and writing a Box2D body's planar state.

A body's origin is the model's origin (for the robot: base_footprint); Box2D's own linear velocity refers to
the centre of mass, so conversions go through the origin explicitly.
"""

from tb3_sim.core.geometry import Pose2D, Twist2D


def body_pose(body):
    """World pose of the body's origin."""
    x, y = body.position
    return Pose2D(x, y, body.angle)


def body_twist_world(body):
    """Velocity of the body's origin in the world frame (vx, vy m/s; wz rad/s)."""
    vx, vy = body.GetLinearVelocityFromLocalPoint((0.0, 0.0))
    return Twist2D(vx, vy, body.angularVelocity)


def set_body_velocity(body, twist_world):
    """Make the body's origin move with `twist_world` (world frame), correcting for the centre of mass."""
    cx, cy = body.worldCenter
    ox, oy = body.position
    wz = twist_world.wz
    body.linearVelocity = (twist_world.vx - wz * (cy - oy), twist_world.vy + wz * (cx - ox))
    body.angularVelocity = wz


def teleport(body, pose, twist_world=Twist2D()):
    """Place the body's origin at `pose` (world frame) moving with `twist_world`, and wake it."""
    body.transform = ((pose.x, pose.y), pose.yaw)
    set_body_velocity(body, twist_world)
    body.awake = True
