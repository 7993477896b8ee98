"""The simulated world: one zero-gravity Box2D world holding the static geometry, the models and the robots.

Time: a fixed physics step of PHYSICS_STEP_S in simulated time; `time_s` is step count x step, so it never
drifts. The caller (the ROS node) decides how fast steps are taken in wall time, publishes /clock, and runs the
sensors at their rates from `time_s`. Physics knows nothing of rendering or ROS.

Gazebo semantics kept: reset_world puts every model (including spawned ones) back to its initial pose and every
robot to its spawn pose with the command zeroed, and keeps sim time running; reset_simulation does the same and
rewinds sim time to 0. Spawned models and robots survive both. Model names follow /gazebo/model_states:
`ground_plane` (only in a world without a floor layer), the world's static models (e.g. `ros_symbol`) in file
order, the world-file models, then robots and spawned models in the order they were added.

Several robots (any TurtleBot3 model each) share the world: they collide with each other and with everything
else, and each one's sensors see the others (`obstacles(excluding=...)`).

At most MAX_MODELS models (robots, world-file and spawned models together; not the ground plane or the static
world geometry) are held: every model costs each LiDAR sweep and each /gazebo/model_states message, so
thousands of spawned boxes would slow the simulator without limit (measured on a 2-core machine: one scan with
100 boxes about the robot takes ~150 ms against ~1 ms with none, model_states 3.6 ms against 0.01 ms). Gazebo has
no such limit; course worlds hold fewer than 10 models.
"""

from typing import NamedTuple

from Box2D import b2

from tb3_sim.core.errors import (
    DuplicateModelError,
    ModelLimitError,
    OverlapError,
    ProtectedModelError,
    UnknownModelError,
)
from tb3_sim.core.geometry import Pose2D, Twist2D
from tb3_sim.core.model_body import ModelBody
from tb3_sim.core.obstacles import model_obstacles, robot_obstacles, static_obstacles
from tb3_sim.core.robot import Robot
from tb3_sim.core.shapes import Box, Circle, Polygon, Segment, visible_at
from tb3_sim.core.turtlebot3 import DEFAULT_MODEL
from tb3_sim.core.world_file import GROUND_PLANE_NAME

# 5 ms (200 Hz), flatland's default rather than Gazebo's 1 ms: the drive acts at 30 Hz and the scan at 5 Hz,
# so 1 ms would buy no accuracy but cost 5x the Python work per simulated second (the real-time-factor
# budget); continuous collision (the robot is a bullet body) stops tunnelling at any commanded speed.
PHYSICS_STEP_S = 0.005
VELOCITY_ITERATIONS = 10
POSITION_ITERATIONS = 10
STATIC_CONTACT_FRICTION = 0.5
MAX_MODELS = 100


class ModelState(NamedTuple):
    """World pose of a model's origin and its twist in the world frame (as /gazebo/get_model_state)."""

    pose: Pose2D
    twist: Twist2D


class World:
    """The simulation: `step()` advances physics; sensors and services read and change state between steps.

    Arguments: `description` (a WorldDescription), the first robot's `robot_pose` (spawn Pose2D of base_footprint,
    world frame), `robot_name` (its model name, e.g. `turtlebot3_waffle`; None: start without a robot, as
    gazebo_ros's empty world) and `robot_model` (a turtlebot3.TurtleBot3Model), `step_s` (physics step, s),
    `clamp_command` (if True commands are clamped to each model's vendor limits; Gazebo does not). More robots
    join with `add_robot`. Sensors are not part of the world: they read it between steps (`obstacles()`,
    `robots()`, `time_s`). Errors are SimError subclasses: DuplicateModelError, UnknownModelError, OverlapError,
    ProtectedModelError, ModelLimitError.
    """

    def __init__(self, description, robot_pose=Pose2D(), robot_name=DEFAULT_MODEL.robot_name,
                 robot_model=DEFAULT_MODEL, step_s=PHYSICS_STEP_S, clamp_command=False):
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
        self._fixed_names = [*self._ground_plane(description), *description.static_model_names]
        self._reserved = set(self._fixed_names)
        self.clamp_command = clamp_command
        self._robots = {}
        self._added = []   # names of robots and spawned models, in the order they joined
        if robot_name is not None:
            self.add_robot(robot_name, robot_model, robot_pose)

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
        now_s = self.time_s
        robots = self._robots.values()
        for robot in robots:
            robot.before_step(now_s)
        self._b2world.Step(self.step_s, VELOCITY_ITERATIONS, POSITION_ITERATIONS)
        for robot in robots:
            robot.after_step(self.step_s)
        return now_s

    def run(self, duration_s):
        """Step until `duration_s` more seconds have passed (rounded to whole steps); for tests and tools."""
        for _ in range(round(duration_s / self.step_s)):
            self.step()

    def obstacles(self, reaching_m=0.0, excluding=None):
        """The geometry now (an `obstacles.Obstacles`): static shapes, models and robots (but not the robot
        `excluding`, the one whose sensor looks) whose top reaches the height `reaching_m` (m above the floor; a
        planar sensor at that height sees only those), by default all."""
        if reaching_m not in self._static_obstacles:
            self._static_obstacles[reaching_m] = static_obstacles(
                [s for s in self.description.static_shapes if visible_at(s, reaching_m)])
        obstacles = self._static_obstacles[reaching_m]
        for model in self._models.values():
            if visible_at(model.spec.shape, reaching_m):
                obstacles = obstacles + model_obstacles(model.spec.shape, model.pose, model.spec.rgb)
        for robot in self._robots.values():
            if robot is not excluding:
                obstacles = obstacles + robot_obstacles(robot.model, robot.pose, reaching_m)
        return obstacles

    @property
    def robot(self):
        """The first robot (the only one in a single-robot world), or None in a world without robots."""
        return next(iter(self._robots.values()), None)

    def robots(self):
        """Every robot, in the order they were added."""
        return list(self._robots.values())

    def add_robot(self, name, model, pose):
        """Add a TurtleBot3 of `model` named `name` with base_footprint at `pose` (also its reset pose).

        Raises DuplicateModelError if the name is taken, OverlapError if its footprint overlaps another robot or
        a model, ModelLimitError if the world holds MAX_MODELS already.
        """
        self._check_free_name(name)
        self._check_model_count()
        placed = _placed(pose)
        for outline in model.footprint():
            self._check_overlap(name, pose, b2.polygonShape(vertices=list(outline)), placed)
        self._robots[name] = Robot(self._b2world, name, pose, model, clamp=self.clamp_command)
        self._added.append(name)
        return self._robots[name]

    def model_names(self):
        """Names for /gazebo/model_states, in Gazebo's order (see the module docstring)."""
        names = list(self._fixed_names)
        file_models = [s.name for s in self.description.models if s.name in self._models]
        return names + file_models + self._added

    @staticmethod
    def _ground_plane(description):
        """[GROUND_PLANE_NAME] for a world on Gazebo's ground plane; [] for a world with a floor layer, whose floor
        model is the ground, as in the course worlds (their .world files include no ground_plane model)."""
        return [GROUND_PLANE_NAME] if description.floor is None else []

    def model_states(self):
        """[(name, ModelState)] for every model, in `model_names()` order."""
        return [(name, self.get_model_state(name)) for name in self.model_names()]

    def has_model(self, name):
        return name in self._reserved or name in self._robots or name in self._models

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
        robot = self._robots.get(name)
        if robot is not None:
            return ModelState(robot.pose, robot.twist_world)
        if name in self._reserved:
            return ModelState(Pose2D(), Twist2D())
        model = self.model(name)
        return ModelState(model.pose, model.twist_world)

    def set_model_state(self, name, pose, twist_world=Twist2D()):
        """Teleport model `name` to `pose` with `twist_world` (world frame). No overlap check (Gazebo has none).

        Raises UnknownModelError, or ProtectedModelError for the ground plane and the static world geometry.
        """
        if name in self._robots:
            self._robots[name].teleport(pose, twist_world)
        elif name in self._reserved:
            raise ProtectedModelError(f"model '{name}' is fixed world geometry and cannot be moved")
        else:
            self.model(name).teleport(pose, twist_world)

    def spawn_model(self, spec):
        """Add the model described by `spec` (a world_file.ModelSpec) at `spec.pose`; that pose is its reset pose.

        Raises DuplicateModelError if the name is taken, OverlapError if its footprint overlaps a robot or
        another model (Box2D's test, which includes its 1 cm polygon skin), ModelLimitError if the world holds
        MAX_MODELS already.
        """
        self._check_free_name(spec.name)
        self._check_model_count()
        self._check_overlap(spec.name, spec.pose, _b2_shape(spec.shape), _placed(spec.pose))
        self._models[spec.name] = ModelBody(self._b2world, self._ground, spec)
        self._added.append(spec.name)

    def delete_model(self, name):
        """Remove a box or cylinder model. Raises UnknownModelError, or ProtectedModelError for the robot,
        the ground plane and the static world geometry."""
        if name in self._robots:
            raise ProtectedModelError(f"model '{name}' is a robot and cannot be deleted")
        if name in self._reserved:
            raise ProtectedModelError(f"model '{name}' is fixed world geometry and cannot be deleted")
        model = self.model(name)
        self._b2world.DestroyBody(model.body)
        del self._models[name]
        if name in self._added:
            self._added.remove(name)

    def reset_world(self):
        """Models back to their initial poses, robots to their spawn poses with a zero command; time keeps
        running."""
        for model in self._models.values():
            model.reset()
        for robot in self._robots.values():
            robot.reset(self.time_s)

    def reset_simulation(self):
        """reset_world plus sim time back to 0 (the sensors restart their own state: see their `reset`)."""
        self._steps = 0
        self.reset_world()

    def _check_free_name(self, name):
        if self.has_model(name):
            raise DuplicateModelError(f"model '{name}' already exists")

    def _check_model_count(self):
        if len(self._models) + len(self._robots) >= MAX_MODELS:
            raise ModelLimitError(f"the world already holds {MAX_MODELS} models (robots included), tb3_sim's "
                                  f"limit: delete a model before spawning another")

    def _check_overlap(self, name, pose, candidate, placed):
        """Raise OverlapError if the Box2D shape `candidate` at transform `placed` overlaps a robot or a model."""
        others = [(r.name, r.body) for r in self._robots.values()] + [(m.name, m.body) for m in self._models.values()]
        for other_name, body in others:
            for fixture in body.fixtures:
                if b2.testOverlap(candidate, 0, fixture.shape, 0, placed, body.transform):
                    raise OverlapError(f"model '{name}' would overlap '{other_name}' at ({pose.x:.3f}, {pose.y:.3f})")

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


def _placed(pose):
    """A Box2D transform at `pose`."""
    placed = b2.transform()
    placed.position, placed.angle = (pose.x, pose.y), pose.yaw
    return placed


def _b2_shape(shape):
    """A free-standing Box2D shape for a model shape, centred on the model origin (for overlap tests)."""
    if isinstance(shape, Box):
        return b2.polygonShape(box=(shape.size_x / 2.0, shape.size_y / 2.0))
    return b2.circleShape(radius=shape.radius)
