"""The Box2D world: driving, odometry, walls (no tunnelling), pushing, spawning, deleting, resets."""

import math

import pytest

from tb3_sim.core.errors import (
    DuplicateModelError,
    ModelLimitError,
    OverlapError,
    ProtectedModelError,
    SimError,
    UnknownModelError,
)
from tb3_sim.core.geometry import Pose2D, Twist2D
from tb3_sim.core.lidar import Lidar
from tb3_sim.core.shapes import Box, Cylinder, Polygon, Segment
from tb3_sim.core.turtlebot3 import WAFFLE
from tb3_sim.core.world import MAX_MODELS, PHYSICS_STEP_S, World
from tb3_sim.core.world_file import ModelSpec, WorldDescription, load_world, shipped_world_path

EMPTY = WorldDescription("empty")


def test_time_advances_in_fixed_steps():
    world = World(EMPTY)
    for _ in range(1000):
        world.step()
    assert world.time_s == pytest.approx(1000 * PHYSICS_STEP_S, abs=1e-12)


def test_odometry_starts_at_the_spawn_pose():
    world = World(EMPTY, robot_pose=Pose2D(-2.0, -0.5, 0.3))
    assert world.robot.pose == pytest.approx((-2.0, -0.5, 0.3), abs=1e-6)
    world.run(1.0)
    assert world.robot.pose == pytest.approx((-2.0, -0.5, 0.3), abs=1e-6), "no command, no motion"


def test_speed_after_a_tenth_of_a_second_of_ramp():
    world = World(EMPTY)
    world.robot.set_command(0.26, 0.0)
    world.run(0.1)
    assert world.robot.twist_body.vx == pytest.approx(0.1, abs=1e-4)


def test_odometry_after_one_second_at_0_2():
    world = World(EMPTY)
    world.robot.set_command(0.2, 0.0)
    world.run(1.0)
    ramp_loss = 0.5 * 0.2 * (0.2 / 1.0)
    x, y, yaw = world.robot.pose
    assert x == pytest.approx(0.2 - ramp_loss, abs=0.005)
    assert y == pytest.approx(0.0, abs=1e-6) and yaw == pytest.approx(0.0, abs=1e-6)
    assert world.robot.twist_body == pytest.approx((0.2, 0.0, 0.0), abs=1e-5)


def test_twist_is_in_the_body_frame_and_world_frame_for_model_state():
    world = World(EMPTY, robot_pose=Pose2D(0.0, 0.0, math.pi / 2))
    world.robot.set_command(0.2, 0.0)
    world.run(1.0)
    assert world.robot.twist_body == pytest.approx((0.2, 0.0, 0.0), abs=1e-5)
    state = world.get_model_state(world.robot.name)
    assert state.twist == pytest.approx((0.0, 0.2, 0.0), abs=1e-5)
    assert state.pose.y == pytest.approx(0.18, abs=0.005)


def test_turning_in_place():
    world = World(EMPTY, robot_pose=Pose2D(1.0, 2.0, 0.0))
    world.robot.set_command(0.0, 1.0)
    world.run(1.5)
    x, y, yaw = world.robot.pose
    ramp_loss = 0.5 * 1.0 * (1.0 * 0.287 / 2)
    assert yaw == pytest.approx(1.5 - ramp_loss, abs=0.02), "30 Hz ramp steps lag the ideal ramp by ~1/60 s"
    assert (x, y) == pytest.approx((1.0, 2.0), abs=1e-3), "the robot turns about base_footprint"
    assert world.robot.twist_body.wz == pytest.approx(1.0, abs=1e-4)
    left, right = world.robot.drive.wheel_angles
    assert left < 0 < right


def test_driving_a_circle():
    world = World(EMPTY)
    world.robot.set_command(0.2, 0.5)
    world.run(2 * math.pi / 0.5 + 0.2)
    x, y, _ = world.robot.pose
    assert math.hypot(x, y) < 0.05, "a full circle of radius 0.4 m comes back near the start"


@pytest.mark.parametrize("speed", [0.26, 1.0, 5.0, 10.0])
@pytest.mark.parametrize("wall", ["thin_segment", "thick_box"])
def test_robot_driven_into_a_wall_stops_at_it_and_never_passes(speed, wall):
    wall_x = 1.0
    shape = (Segment((wall_x, -2.0), (wall_x, 2.0)) if wall == "thin_segment"
             else Polygon(((wall_x, -2.0), (wall_x + 0.1, -2.0), (wall_x + 0.1, 2.0), (wall_x, 2.0))))
    world = World(WorldDescription("wall", "wall", (shape,)))
    world.robot.drive.acceleration_mps2 = 0.0  # no ramp: hit the wall at the full commanded speed
    world.robot.set_command(speed, 0.0)
    furthest = -math.inf
    for _ in range(round((1.0 / speed + 1.0) / PHYSICS_STEP_S)):
        world.step()
        furthest = max(furthest, world.robot.pose.x + WAFFLE.body_x_max_m)
    assert furthest <= wall_x + 0.005
    front = world.robot.pose.x + WAFFLE.body_x_max_m
    assert wall_x - 0.03 <= front <= wall_x
    assert abs(world.robot.twist_body.vx) < 0.05


def test_robot_pushes_a_dynamic_box_and_the_box_then_stops():
    world = World(EMPTY)
    world.spawn_model(ModelSpec("crate", Box(0.3, 0.3, 0.3), Pose2D(0.5, 0.0, 0.0)))
    world.robot.set_command(0.2, 0.0)
    world.run(4.0)
    pushed = world.get_model_state("crate").pose.x
    assert pushed > 0.9
    world.robot.set_command(0.0, 0.0)
    world.run(1.0)
    state = world.get_model_state("crate")
    assert math.hypot(state.twist.vx, state.twist.vy) < 1e-3, "floor friction stops the box"


def test_ramped_drive_into_a_wall_from_a_long_run_up_never_passes():
    world = World(WorldDescription("wall", "wall", (Segment((1.0, -2.0), (1.0, 2.0)),)), Pose2D(-12.0, 0.0, 0.0))
    world.robot.set_command(5.0, 0.0)
    furthest = -math.inf
    for _ in range(round(6.0 / PHYSICS_STEP_S)):
        world.step()
        furthest = max(furthest, world.robot.pose.x + WAFFLE.body_x_max_m)
    assert 0.97 <= furthest <= 1.005


def test_static_model_is_not_pushed():
    world = World(EMPTY)
    world.spawn_model(ModelSpec("pillar", Cylinder(0.1, 0.5), Pose2D(0.5, 0.0, 0.0), static=True))
    world.robot.set_command(0.26, 0.0)
    world.run(4.0)
    assert world.get_model_state("pillar").pose == pytest.approx((0.5, 0.0, 0.0))
    assert world.robot.pose.x + WAFFLE.body_x_max_m <= 0.4 + 1e-3


def test_model_names_in_gazebo_order():
    world = World(load_world(shipped_world_path("approach_arena")), robot_name="turtlebot3_waffle")
    world.spawn_model(ModelSpec("box1", Box(0.2, 0.2, 0.2), Pose2D(-0.6, 1.0, 0.0)))
    assert world.model_names() == ["ground_plane", "approach_arena", "target_box", "side_box", "post",
                                   "turtlebot3_waffle", "box1"]
    states = dict(world.model_states())
    assert states["ground_plane"].pose == (0.0, 0.0, 0.0)
    assert states["box1"].pose == pytest.approx((-0.6, 1.0, 0.0))
    tb3 = World(load_world(shipped_world_path("turtlebot3_world")), Pose2D(-2.0, -0.5, 0.0))
    assert tb3.model_names() == ["ground_plane", "ros_symbol", "turtlebot3_waffle"]


@pytest.mark.parametrize("name", ["box1", "turtlebot3_waffle", "ground_plane", "approach_arena", "target_box"])
def test_spawn_with_a_taken_name_fails(name):
    world = World(load_world(shipped_world_path("approach_arena")))
    world.spawn_model(ModelSpec("box1", Box(0.2, 0.2, 0.2), Pose2D(-0.6, 1.0, 0.0)))
    with pytest.raises(DuplicateModelError, match="already exists"):
        world.spawn_model(ModelSpec(name, Box(0.2, 0.2, 0.2), Pose2D(-0.6, -1.0, 0.0)))


def test_spawn_overlapping_the_robot_or_a_model_fails():
    world = World(EMPTY, robot_pose=Pose2D(0.0, 0.0, 0.0))
    with pytest.raises(OverlapError, match="turtlebot3_waffle"):
        world.spawn_model(ModelSpec("on_robot", Box(0.2, 0.2, 0.2), Pose2D(0.1, 0.0, 0.0)))
    with pytest.raises(OverlapError):
        world.spawn_model(ModelSpec("on_wheel", Cylinder.sphere(0.05), Pose2D(0.0, 0.18, 0.0)))
    world.spawn_model(ModelSpec("box1", Box(0.4, 0.4, 0.4), Pose2D(1.0, 0.0, 0.0)))
    with pytest.raises(OverlapError, match="box1"):
        world.spawn_model(ModelSpec("box2", Cylinder(0.1, 0.3), Pose2D(1.25, 0.0, 0.0)))
    world.spawn_model(ModelSpec("box2", Cylinder(0.1, 0.3), Pose2D(1.35, 0.0, 0.0)))
    assert world.has_model("box2") and not world.has_model("on_robot")


def test_spawns_past_the_model_limit_are_refused_until_one_is_deleted():
    world = World(EMPTY, robot_pose=Pose2D(0.0, 0.0, 0.0))
    for i in range(MAX_MODELS - 1):   # the robot is the first of MAX_MODELS
        world.spawn_model(ModelSpec(f"box{i}", Box(0.2, 0.2, 0.2), Pose2D(1.0 + i % 10, 1.0 + i // 10, 0.0)))
    with pytest.raises(ModelLimitError, match=f"already holds {MAX_MODELS} models"):
        world.spawn_model(ModelSpec("one_more", Box(0.2, 0.2, 0.2), Pose2D(-5.0, 0.0, 0.0)))
    with pytest.raises(ModelLimitError):
        world.add_robot("robot_2", WAFFLE, Pose2D(-5.0, 0.0, 0.0))
    world.delete_model("box0")
    world.spawn_model(ModelSpec("one_more", Box(0.2, 0.2, 0.2), Pose2D(-5.0, 0.0, 0.0)))


def test_delete_rules():
    world = World(load_world(shipped_world_path("approach_arena")))
    with pytest.raises(ProtectedModelError, match="robot"):
        world.delete_model("turtlebot3_waffle")
    for fixed in ("ground_plane", "approach_arena"):
        with pytest.raises(ProtectedModelError):
            world.delete_model(fixed)
    with pytest.raises(UnknownModelError, match="nope"):
        world.delete_model("nope")
    world.delete_model("target_box")
    assert "target_box" not in world.model_names()
    with pytest.raises(UnknownModelError):
        world.get_model_state("target_box")


def test_every_error_shares_one_root():
    for error in (DuplicateModelError, OverlapError, ProtectedModelError, UnknownModelError):
        assert issubclass(error, SimError)


def test_set_model_state_teleports_and_sets_velocity():
    world = World(load_world(shipped_world_path("approach_arena")))
    world.set_model_state("turtlebot3_waffle", Pose2D(0.5, -0.5, 1.0))
    assert world.robot.pose == pytest.approx((0.5, -0.5, 1.0), abs=1e-6)
    world.set_model_state("target_box", Pose2D(2.0, 1.0, 0.0), Twist2D(0.5, 0.0, 0.0))
    assert world.get_model_state("target_box").twist.vx == pytest.approx(0.5)
    with pytest.raises(ProtectedModelError):
        world.set_model_state("approach_arena", Pose2D())


def drive_and_disturb(world):
    world.robot.set_command(0.2, 0.4)
    world.spawn_model(ModelSpec("spawned", Box(0.2, 0.2, 0.2), Pose2D(-0.6, 1.0, 0.0)))
    world.set_model_state("target_box", Pose2D(2.5, 1.0, 0.2))
    world.set_model_state("spawned", Pose2D(-0.6, -1.0, 0.0))
    world.run(2.0)


def assert_back_at_start(world):
    assert world.robot.pose == pytest.approx((0.0, 0.0, 0.0), abs=1e-6)
    assert world.get_model_state("target_box").pose == pytest.approx((1.5, 0.0, 0.0), abs=1e-6)
    assert world.get_model_state("spawned").pose == pytest.approx((-0.6, 1.0, 0.0), abs=1e-6)
    assert world.robot.drive.command == (0.0, 0.0)
    world.run(1.0)
    assert world.robot.pose == pytest.approx((0.0, 0.0, 0.0), abs=1e-6), "the robot stays still after reset"


def test_reset_world_keeps_time_and_spawned_models():
    world = World(load_world(shipped_world_path("approach_arena")))
    drive_and_disturb(world)
    world.reset_world()
    assert world.time_s == pytest.approx(2.0)
    assert_back_at_start(world)


def test_reset_simulation_rewinds_time_and_repeats_the_run():
    world, lidar = World(load_world(shipped_world_path("approach_arena"))), Lidar(seed=4)
    world.robot.set_command(0.2, 0.4)
    world.run(1.0)
    first_pose, first_scan = world.robot.pose, lidar.read(world, world.robot, world.time_s).ranges
    drive_and_disturb(world)
    world.reset_simulation()
    assert world.time_s == 0.0
    assert_back_at_start(world)
    world.delete_model("spawned")
    world.reset_simulation()
    lidar.reset()
    world.robot.set_command(0.2, 0.4)
    world.run(1.0)
    assert world.robot.pose == pytest.approx(first_pose, abs=1e-4)
    assert lidar.read(world, world.robot, world.time_s).ranges == pytest.approx(first_scan, abs=1e-3)


def test_robot_start_in_turtlebot3_world_is_clear_and_sees_the_wall_behind():
    world = World(load_world(shipped_world_path("turtlebot3_world")), Pose2D(-2.0, -0.5, 0.0))
    ranges = Lidar().read(world, world.robot, world.time_s).ranges
    inner_wall_x_at_y = -2.93 + 0.5 / math.tan(math.radians(60))
    assert ranges[180] == pytest.approx(-2.064 - inner_wall_x_at_y, abs=0.05)
    world.robot.set_command(0.26, 0.0)
    world.run(1.0)
    assert world.robot.pose.x == pytest.approx(-2.0 + 0.26 - 0.5 * 0.26 ** 2, abs=0.01)


def test_optional_clamp_to_the_waffle_limits():
    world = World(EMPTY, clamp_command=True)
    world.robot.set_command(1.0, 0.0)
    world.run(2.0)
    assert world.robot.twist_body.vx == pytest.approx(0.26, abs=1e-5)
