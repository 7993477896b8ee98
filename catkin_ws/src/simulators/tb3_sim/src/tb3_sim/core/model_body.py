"""A named model in the world: one Box2D body with one box or cylinder shape."""

import math

from tb3_sim.core.bodies import body_pose, body_twist_world, teleport
from tb3_sim.core.geometry import Twist2D
from tb3_sim.core.shapes import Box

# Coulomb friction with the floor (ODE's default mu = 1 for a spawned box), emulated top-down with a Box2D
# friction joint to the ground: without it a pushed box would glide forever in a zero-gravity 2D world.
FLOOR_FRICTION_COEFF = 1.0
STANDARD_GRAVITY_MPS2 = 9.81
MODEL_CONTACT_FRICTION = 0.5


class ModelBody:
    """A box or cylinder model. `spec.pose` is its initial pose, where reset_world puts it back.

    Static models have a static body (never pushed, movable only by `teleport`); dynamic ones have `spec.mass_kg`
    and floor friction.
    """

    def __init__(self, b2world, ground_body, spec):
        self.spec = spec
        pose = spec.pose
        if spec.static:
            self.body = b2world.CreateStaticBody(position=(pose.x, pose.y), angle=pose.yaw)
        else:
            self.body = b2world.CreateDynamicBody(position=(pose.x, pose.y), angle=pose.yaw)
        shape = spec.shape
        if isinstance(shape, Box):
            area = shape.size_x * shape.size_y
            fixture = self.body.CreatePolygonFixture(box=(shape.size_x / 2.0, shape.size_y / 2.0),
                                                     density=spec.mass_kg / area, friction=MODEL_CONTACT_FRICTION)
        else:
            area = math.pi * shape.radius ** 2
            fixture = self.body.CreateCircleFixture(radius=shape.radius, density=spec.mass_kg / area,
                                                    friction=MODEL_CONTACT_FRICTION)
        self.fixture = fixture
        if not spec.static:
            max_force = FLOOR_FRICTION_COEFF * spec.mass_kg * STANDARD_GRAVITY_MPS2
            b2world.CreateFrictionJoint(bodyA=ground_body, bodyB=self.body, localAnchorA=(0.0, 0.0),
                                        localAnchorB=self.body.localCenter, maxForce=max_force,
                                        maxTorque=max_force * _friction_arm_m(shape))

    @property
    def name(self):
        return self.spec.name

    @property
    def pose(self):
        """World pose of the model origin."""
        return body_pose(self.body)

    @property
    def twist_world(self):
        """Velocity of the model origin in the world frame."""
        return body_twist_world(self.body)

    def teleport(self, pose, twist_world=Twist2D()):
        """Put the model at `pose` (world) with `twist_world` (ignored by static models)."""
        teleport(self.body, pose, twist_world)

    def reset(self):
        """Back to the initial pose, at rest."""
        self.teleport(self.spec.pose)


def _friction_arm_m(shape):
    """Mean lever arm of uniform floor friction over the footprint (2/3 r for a disc; box: a close estimate)."""
    if isinstance(shape, Box):
        return (shape.size_x + shape.size_y) / 6.0
    return 2.0 * shape.radius / 3.0
