"""A TurtleBot3 (any model of core.turtlebot3) as a Box2D body driven by the Gazebo-style differential drive."""

import math

from tb3_sim.core.bodies import body_pose, body_twist_world, set_body_velocity, teleport
from tb3_sim.core.diff_drive import DiffDrive
from tb3_sim.core.geometry import Pose2D, Twist2D
from tb3_sim.core.turtlebot3 import DEFAULT_MODEL

# Contact friction of the robot's shapes with walls and boxes (Gazebo gives the wheels mu 0.1).
ROBOT_CONTACT_FRICTION = 0.1


def _polygon_area(points):
    return 0.5 * abs(sum(x0 * y1 - x1 * y0 for (x0, y0), (x1, y1) in zip(points, points[1:] + points[:1])))


class Robot:
    """The robot: a dynamic, bullet (continuous-collision) body whose velocity the drive sets each step.

    The body's origin is base_footprint; its collision shapes are the model's base box and wheels
    (`TurtleBot3Model.footprint`) with the model's total mass. The drive uses the model's wheel separation and
    radius; `clamp` limits commands to the model's vendor limits (Gazebo does not). Because the velocity is
    overwritten before every physics step, the contact solver is what stops the robot at walls and what lets it
    push dynamic models, as in flatland's diff drive.
    """

    def __init__(self, b2world, name, spawn_pose, model=DEFAULT_MODEL, clamp=False):
        self.name = name
        self.model = model
        self.spawn_pose = Pose2D(*spawn_pose)
        limits = (model.max_linear_mps, model.max_angular_radps) if clamp else None
        self.drive = DiffDrive(model.wheel_separation_m, model.wheel_radius_m, limits=limits)
        outlines = model.footprint()
        density = model.mass_kg / sum(_polygon_area(list(p)) for p in outlines)
        self.body = b2world.CreateDynamicBody(position=(self.spawn_pose.x, self.spawn_pose.y),
                                              angle=self.spawn_pose.yaw, bullet=True, allowSleep=False)
        for outline in outlines:
            self.body.CreatePolygonFixture(vertices=list(outline), density=density,
                                           friction=ROBOT_CONTACT_FRICTION)

    def set_command(self, linear_mps, angular_radps):
        """Hold a velocity command (m/s, rad/s; no timeout, no clamp); raises InvalidCommandError."""
        self.drive.set_command(linear_mps, angular_radps)

    def before_step(self, now_s):
        """Step hook: update the drive at `now_s` and drive the body with its (v, w) along the heading."""
        self.drive.update(now_s)
        linear, angular = self.drive.velocity
        yaw = self.body.angle
        set_body_velocity(self.body, Twist2D(linear * math.cos(yaw), linear * math.sin(yaw), angular))

    def after_step(self, dt_s):
        """Step hook: turn the wheels by the time just simulated."""
        self.drive.advance_wheels(dt_s)

    @property
    def pose(self):
        """World pose of base_footprint; this is also /odom's pose (Gazebo's `world` odometry source)."""
        return body_pose(self.body)

    @property
    def twist_world(self):
        """Velocity of base_footprint in the world frame (what /gazebo/get_model_state reports)."""
        return body_twist_world(self.body)

    @property
    def twist_body(self):
        """Velocity of base_footprint in its own frame (what /odom reports; vy is ~0 unless pushed sideways)."""
        return self.twist_world.rotated(-self.body.angle)

    def scan_pose(self):
        """World pose of base_scan projected on the floor (the Waffle's is 6.4 cm behind base_footprint)."""
        pose = self.pose
        x, y = pose.compose(self.model.scan_x_m, 0.0)
        return Pose2D(x, y, pose.yaw)

    def teleport(self, pose, twist_world=Twist2D()):
        """Put base_footprint at `pose` (world) with `twist_world`; the drive takes over at the next step."""
        teleport(self.body, pose, twist_world)

    def reset(self, now_s):
        """Back to the spawn pose, at rest, with the command and wheel angles zeroed."""
        self.drive.reset(now_s)
        self.teleport(self.spawn_pose)
