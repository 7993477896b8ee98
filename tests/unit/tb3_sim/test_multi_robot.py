"""Several TurtleBot3s in one world: each model's numbers, collisions between robots, robots seen by each other's
LiDAR, Gazebo's model order, spawning TurtleBot3 URDFs, and how a spawned robot's topics and frames are named."""
import math

import numpy as np
import pytest

from tb3_sim.core.errors import BadRequestError, DuplicateModelError, OverlapError
from tb3_sim.core.geometry import Pose2D
from tb3_sim.core.lidar import Lidar
from tb3_sim.core.model_xml import TurtleBot3Spec, parse_model_xml
from tb3_sim.core.physics_properties import PhysicsProperties, physics_properties
from tb3_sim.core.turtlebot3 import BURGER, TURTLEBOT3_MODELS, WAFFLE, WAFFLE_PI, model_named
from tb3_sim.core.world import World
from tb3_sim.core.world_file import WorldDescription
from tb3_sim.ros.robot_naming import RobotNaming, absolute_namespace, spawned_robot_naming

EMPTY = WorldDescription("empty")


def robot_free_world():
    return World(EMPTY, robot_name=None)


@pytest.mark.parametrize("model, separation, scan_x, scan_height, limits, camera", [
    (BURGER, 0.160, -0.032, 0.182, (0.22, 2.84), None),
    (WAFFLE, 0.287, -0.064, 0.132, (0.26, 1.82), (1920, 1080, True)),
    (WAFFLE_PI, 0.287, -0.064, 0.132, (0.26, 1.82), (640, 480, False)),
])
def test_each_model_has_its_own_numbers(model, separation, scan_x, scan_height, limits, camera):
    assert model_named(model.name) is model and model.robot_name == f"turtlebot3_{model.name}"
    assert (model.wheel_separation_m, model.scan_x_m, model.scan_height_m) == (separation, scan_x, scan_height)
    assert (model.max_linear_mps, model.max_angular_radps) == limits
    if camera is None:
        assert model.camera is None
    else:
        assert (model.camera.width_px, model.camera.height_px, model.camera.depth_range_m is not None) == camera
    children = {child for _, child, _, _ in model.static_transforms}
    assert {"base_link", "base_scan", "imu_link"} <= children
    assert ("camera_rgb_optical_frame" in children) == (camera is not None)


def test_unknown_model_names_the_choices():
    with pytest.raises(KeyError, match="burger, waffle, waffle_pi"):
        model_named("wafle")


def test_a_burger_drives_with_its_own_wheel_separation():
    world = World(EMPTY, robot_name="turtlebot3_burger", robot_model=BURGER)
    world.robot.drive.acceleration_mps2 = 0.0
    world.robot.set_command(0.0, 1.0)
    world.run(1.0)
    left, right = world.robot.drive.wheel_angles
    assert right == pytest.approx(1.0 * 0.160 / 2 / 0.033, rel=0.05) and left == pytest.approx(-right)
    assert world.robot.pose.yaw == pytest.approx(1.0, abs=0.05)


def test_robots_are_added_in_order_after_the_file_models_and_are_not_deletable():
    world = robot_free_world()
    assert world.robot is None and world.model_names() == ["ground_plane"]
    world.add_robot("tb3_0", WAFFLE, Pose2D(-1.0, 0.0, 0.0))
    world.add_robot("tb3_1", BURGER, Pose2D(1.0, 0.0, math.pi))
    assert world.model_names() == ["ground_plane", "tb3_0", "tb3_1"]
    assert world.robot.name == "tb3_0" and [r.model for r in world.robots()] == [WAFFLE, BURGER]
    with pytest.raises(DuplicateModelError):
        world.add_robot("tb3_1", WAFFLE, Pose2D(3.0, 0.0, 0.0))
    with pytest.raises(OverlapError, match="'tb3_2' would overlap 'tb3_1'"):
        world.add_robot("tb3_2", WAFFLE, Pose2D(1.1, 0.0, 0.0))


def test_two_robots_driving_head_on_collide_instead_of_passing_through():
    world = robot_free_world()
    left = world.add_robot("tb3_0", WAFFLE, Pose2D(-1.0, 0.0, 0.0))
    right = world.add_robot("tb3_1", WAFFLE, Pose2D(1.0, 0.0, math.pi))
    left.set_command(0.26, 0.0)
    right.set_command(0.26, 0.0)
    world.run(8.0)
    # Face to face the fronts meet: each front is 0.069 m ahead of its base_footprint.
    assert left.pose.x < right.pose.x
    assert right.pose.x - left.pose.x == pytest.approx(2 * 0.069, abs=0.03)


def test_each_robots_lidar_sees_the_other_robot_but_not_itself():
    world = robot_free_world()
    looking = world.add_robot("tb3_0", WAFFLE, Pose2D(0.0, 0.0, 0.0))
    world.add_robot("tb3_1", WAFFLE, Pose2D(1.0, 0.0, math.pi))
    ranges = Lidar(noise_stddev_m=0.0).read(world, looking, 0.0).ranges
    # The other Waffle's LiDAR housing (r 0.055 m, 1.5 cm ahead of its base_scan) is the part in this scan plane.
    housing_x = 1.0 + 0.064 - 0.015
    assert ranges[0] == pytest.approx(housing_x - 0.055 + 0.064, abs=0.005)
    assert np.isposinf(ranges[180]), "its own body is never seen"


def test_a_turtlebot3_urdf_is_read_as_that_robot_whatever_its_links():
    urdf = '<?xml version="1.0"?><robot name="turtlebot3_waffle_pi"><link name="base_footprint"/>' \
           '<link name="base_link"><collision><geometry><box size="1 1 1"/></geometry></collision></link></robot>'
    assert parse_model_xml(urdf, urdf_only=True) == TurtleBot3Spec("turtlebot3_waffle_pi", WAFFLE_PI)
    assert {m.robot_name for m in TURTLEBOT3_MODELS.values()} == {
        "turtlebot3_burger", "turtlebot3_waffle", "turtlebot3_waffle_pi"}


@pytest.mark.parametrize("namespace, tf_prefix_param, expected", [
    ("/", None, RobotNaming("/", "")),
    ("", None, RobotNaming("/", "")),
    ("/tb3_0/", None, RobotNaming("/tb3_0/", "tb3_0")),
    ("tb3_0", None, RobotNaming("/tb3_0/", "tb3_0")),
    ("/robots/tb3_1", None, RobotNaming("/robots/tb3_1/", "robots/tb3_1")),
    ("/tb3_0/", "/my_prefix", RobotNaming("/tb3_0/", "my_prefix")),
    ("/tb3_0/", "", RobotNaming("/tb3_0/", "tb3_0")),
])
def test_spawned_robots_are_named_as_gazebo_ros_plugins_name_them(namespace, tf_prefix_param, expected):
    naming = spawned_robot_naming(namespace, tf_prefix_param)
    assert naming == expected
    assert absolute_namespace(namespace) == expected.namespace


def test_naming_prefixes_topics_frames_and_fixed_joints():
    naming = RobotNaming("/tb3_2/", "tb3_2")
    assert (naming.topic("cmd_vel"), naming.frame("odom")) == ("/tb3_2/cmd_vel", "tb3_2/odom")
    parent, child, xyz, _ = naming.transforms(WAFFLE.static_transforms)[0]
    assert (parent, child, xyz) == ("tb3_2/base_footprint", "tb3_2/base_link", (0.0, 0.0, 0.010))
    assert (RobotNaming().topic("odom"), RobotNaming().frame("odom")) == ("odom", "odom")


def test_physics_properties_set_the_real_time_factor_as_gazebo_computes_it():
    assert PhysicsProperties.for_pacing(0.005, 1.0) == PhysicsProperties(0.005, 200.0)
    assert physics_properties(0.001, 5000.0, (0.0, 0.0, -9.8)).real_time_factor == pytest.approx(5.0)
    assert physics_properties(0.001, 0.0, (0.0, 0.0, -9.8)).real_time_factor == 0.0
    assert physics_properties(0.001, 10.0, (0.0, 0.0, -9.8)).real_time_factor == pytest.approx(0.01)


@pytest.mark.parametrize("time_step, rate, gravity, field", [
    (0.0, 1000.0, (0, 0, -9.8), "time_step"), (math.nan, 1000.0, (0, 0, -9.8), "time_step"),
    (0.001, -1.0, (0, 0, -9.8), "max_update_rate"), (0.001, math.inf, (0, 0, -9.8), "max_update_rate"),
    (0.001, 1000.0, (0, math.nan, -9.8), "gravity"),
    (0.001, 1e-9, (0, 0, -9.8), "real-time factor"), (0.001, 0.0001, (0, 0, -9.8), "real-time factor"),
    (0.001, 9.0, (0, 0, -9.8), "real-time factor"), (1e300, 1e300, (0, 0, -9.8), "real-time factor"),
])
def test_bad_physics_properties_are_refused_naming_the_field(time_step, rate, gravity, field):
    with pytest.raises(BadRequestError, match=field):
        physics_properties(time_step, rate, gravity)
