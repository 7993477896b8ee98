"""The simulated world: one zero-gravity Box2D world holding the static geometry, the models and the robot.

Time: a fixed physics step of PHYSICS_STEP_S in simulated time; `time_s` is step count x step, so it never
drifts. The caller (the ROS node) decides how fast steps are taken in wall time, publishes /clock, and runs the
sensors at their rates from `time_s`. Physics knows nothing of rendering or ROS.

Gazebo semantics kept (spec §5): reset_world puts every model (including spawned ones) back to its initial pose
and the robot to its spawn pose with the command zeroed, and keeps sim time running; reset_simulation does the
same and rewinds sim time to 0. Spawned models survive both. Model names follow /gazebo/model_states:
`ground_plane`, the world's static model (e.g. `ros_symbol`), the world-file models, the robot, then spawned
models, in that order.
"""

from typing import NamedTuple

from Box2D import b2

from tb3_sim.core.diff_drive import DiffDrive
from tb3_sim.core.errors import DuplicateModelError, OverlapError, ProtectedModelError, UnknownModelError
from tb3_sim.core.geometry import Pose2D, Twist2D
from tb3_sim.core.model_body import ModelBody
from tb3_sim.core.obstacles import model_obstacles, static_obstacles
from tb3_sim.core.robot import Robot
from tb3_sim.core.shapes import Box, Circle, Polygon, Segment, visible_at
from tb3_sim.core.waffle import WAFFLE_MODEL_NAME
from tb3_sim.core.world_file import GROUND_PLANE_NAME

# 5 ms (200 Hz), flatland's default rather than Gazebo's 1 ms: the drive acts at 30 Hz and the scan at 5 Hz,
# so 1 ms would buy no accuracy but cost 5x the Python work per simulated second (the real-time-factor
# budget); continuous collision (the robot is a bullet body) stops tunnelling at any commanded speed.
PHYSICS_STEP_S = 0.005
VELOCITY_ITERATIONS = 10
POSITION_ITERATIONS = 10
STATIC_CONTACT_FRICTION = 0.5


class ModelState(NamedTuple):
    """World pose of a model's origin and its twist in the world frame (as /gazebo/get_model_state)."""

    pose: Pose2D
    twist: Twist2D


class World:
    """The simulation: `step()` advances physics; sensors and services read and change state between steps.

    Arguments: `description` (a WorldDescription), `robot_pose` (spawn Pose2D of base_footprint, world frame),
    `robot_name` (model name of the robot, e.g. `turtlebot3_waffle`), `step_s` (physics step, s),
    `clamp_command` (if True commands are clamped to the Waffle's 0.26 m/s and 1.82 rad/s; Gazebo does not).
    Sensors are not part of the world: they read it between steps (`obstacles()`, `robot`, `time_s`).
    Errors are SimError subclasses: DuplicateModelError, UnknownModelError, OverlapError, ProtectedModelError.
    """

    def __init__(self, description, robot_pose=Pose2D(), robot_name=WAFFLE_MODEL_NAME, step_s=PHYSICS_STEP_S,
                 clamp_command=False):
        self.description = description
        self.step_s = step_s
        self._steps = 0
        self._b2world = b2.world(gravity=(0.0, 0.0), doSleep=True)
        self._ground = self._b2world.CreateStaticBody()
        for shape in description.static_shapes:
            self._add_static_shape(shape)
        self._static_obstacles = {}
        self._models = {}
        for spec in description.models:
            self._models[spec.name] = ModelBody(self._b2world, self._ground, spec)
        self._reserved = {GROUND_PLANE_NAME}
        if description.static_model:
            self._reserved.add(description.static_model)
        if robot_name in self._reserved or robot_name in self._models:
            raise DuplicateModelError(f"robot name '{robot_name}' is already used by the world")
        self.robot = Robot(self._b2world, robot_name, robot_pose, DiffDrive(clamp=clamp_command))

    @property
    def time_s(self):
        """Simulated time in seconds since the start or the last reset_simulation."""
        return self._steps * self.step_s

    def step(self):
        """Advance physics by one step and return the new time_s.

        As in Gazebo's World::Update, sim time advances first and the plugins (here the drive) act at the new
        time, then physics integrates the step; so a 30 Hz update due at t = 0.1 s shapes the motion up to 0.1 s.
        """
        self._steps += 1
        self.robot.before_step(self.time_s)
        self._b2world.Step(self.step_s, VELOCITY_ITERATIONS, POSITION_ITERATIONS)
        self.robot.after_step(self.step_s)
        return self.time_s

    def run(self, duration_s):
        """Step until `duration_s` more seconds have passed (rounded to whole steps); for tests and tools."""
        for _ in range(round(duration_s / self.step_s)):
            self.step()

    def obstacles(self, reaching_m=0.0):
        """The geometry now (an `obstacles.Obstacles`): static shapes and models whose top reaches the height
        `reaching_m` (m above the floor; a planar sensor at that height sees only those), by default all."""
        if reaching_m not in self._static_obstacles:
            self._static_obstacles[reaching_m] = static_obstacles(
                [s for s in self.description.static_shapes if visible_at(s, reaching_m)])
        obstacles = self._static_obstacles[reaching_m]
        for model in self._models.values():
            if visible_at(model.spec.shape, reaching_m):
                obstacles = obstacles + model_obstacles(model.spec.shape, model.pose, model.spec.rgb)
        return obstacles

    def model_names(self):
        """Names for /gazebo/model_states, in Gazebo's order (see the module docstring)."""
        names = [GROUND_PLANE_NAME]
        if self.description.static_model:
            names.append(self.description.static_model)
        file_models = [s.name for s in self.description.models if s.name in self._models]
        spawned = [n for n in self._models if n not in file_models]
        return names + file_models + [self.robot.name] + spawned

    def model_states(self):
        """[(name, ModelState)] for every model, in `model_names()` order."""
        return [(name, self.get_model_state(name)) for name in self.model_names()]

    def has_model(self, name):
        return name in self._reserved or name == self.robot.name or name in self._models

    def model(self, name):
        """The `ModelBody` of a box or cylinder model; raises UnknownModelError."""
        if name not in self._models:
            raise UnknownModelError(f"model '{name}' does not exist")
        return self._models[name]

    def models(self):
        """The box and cylinder models (not the robot), in insertion order."""
        return list(self._models.values())

    def get_model_state(self, name):
        """Pose and world-frame twist of the model `name`; raises UnknownModelError."""
        if name == self.robot.name:
            return ModelState(self.robot.pose, self.robot.twist_world)
        if name in self._reserved:
            return ModelState(Pose2D(), Twist2D())
        model = self.model(name)
        return ModelState(model.pose, model.twist_world)

    def set_model_state(self, name, pose, twist_world=Twist2D()):
        """Teleport model `name` to `pose` with `twist_world` (world frame). No overlap check (Gazebo has none).

        Raises UnknownModelError, or ProtectedModelError for the ground plane and the static world geometry.
        """
        if name == self.robot.name:
            self.robot.teleport(pose, twist_world)
        elif name in self._reserved:
            raise ProtectedModelError(f"model '{name}' is fixed world geometry and cannot be moved")
        else:
            self.model(name).teleport(pose, twist_world)

    def spawn_model(self, spec):
        """Add the model described by `spec` (a world_file.ModelSpec) at `spec.pose`; that pose is its reset pose.

        Raises DuplicateModelError if the name is taken, OverlapError if its footprint overlaps the robot or
        another model (Box2D's test, which includes its 1 cm polygon skin).
        """
        self._check_free_name(spec.name)
        candidate = _b2_shape(spec.shape)
        placed = b2.transform()
        placed.position, placed.angle = (spec.pose.x, spec.pose.y), spec.pose.yaw
        others = [(self.robot.name, self.robot.body)] + [(m.name, m.body) for m in self._models.values()]
        for other_name, body in others:
            for fixture in body.fixtures:
                if b2.testOverlap(candidate, 0, fixture.shape, 0, placed, body.transform):
                    raise OverlapError(f"model '{spec.name}' would overlap '{other_name}' at "
                                       f"({spec.pose.x:.3f}, {spec.pose.y:.3f})")
        self._models[spec.name] = ModelBody(self._b2world, self._ground, spec)

    def delete_model(self, name):
        """Remove a box or cylinder model. Raises UnknownModelError, or ProtectedModelError for the robot,
        the ground plane and the static world geometry."""
        if name == self.robot.name:
            raise ProtectedModelError(f"model '{name}' is the robot and cannot be deleted")
        if name in self._reserved:
            raise ProtectedModelError(f"model '{name}' is fixed world geometry and cannot be deleted")
        model = self.model(name)
        self._b2world.DestroyBody(model.body)
        del self._models[name]

    def reset_world(self):
        """Models back to their initial poses, robot to its spawn pose with a zero command; time keeps running."""
        for model in self._models.values():
            model.reset()
        self.robot.reset(self.time_s)

    def reset_simulation(self):
        """reset_world plus sim time back to 0 (the sensors restart their own state: see their `reset`)."""
        self._steps = 0
        self.reset_world()

    def _check_free_name(self, name):
        if self.has_model(name):
            raise DuplicateModelError(f"model '{name}' already exists")

    def _add_static_shape(self, shape):
        if isinstance(shape, Segment):
            self._ground.CreateEdgeFixture(vertices=[shape.start, shape.end], friction=STATIC_CONTACT_FRICTION)
        elif isinstance(shape, Polygon):
            self._ground.CreatePolygonFixture(vertices=list(shape.points), friction=STATIC_CONTACT_FRICTION)
        elif isinstance(shape, Circle):
            self._ground.CreateCircleFixture(pos=shape.center, radius=shape.radius,
                                             friction=STATIC_CONTACT_FRICTION)
        else:
            raise TypeError(f"not a static shape: {shape!r}")


def _b2_shape(shape):
    """A free-standing Box2D shape for a model shape, centred on the model origin (for overlap tests)."""
    if isinstance(shape, Box):
        return b2.polygonShape(box=(shape.size_x / 2.0, shape.size_y / 2.0))
    return b2.circleShape(radius=shape.radius)
