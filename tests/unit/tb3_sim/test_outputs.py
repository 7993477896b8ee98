"""The output seam: every periodic output registered once, published at Gazebo's rates in sim time, lazy ones
quiet without subscribers, all restarted by a reset (fake publishers, no master)."""
import json
from collections import Counter

import pytest

from tb3_sim.core.geometry import Pose2D
from tb3_sim.core.turtlebot3 import BURGER, WAFFLE_PI
from tb3_sim.core.world import World
from tb3_sim.core.world_file import load_world, shipped_world_path
from tb3_sim.ros.config import SimConfig
from tb3_sim.ros.outputs import Output, OutputPublisher, robot_outputs, world_outputs
from tb3_sim.ros.outputs.clock import ClockOutput
from tb3_sim.ros.outputs.scan import ScanOutput
from tb3_sim.ros.robot_naming import RobotNaming

TOPIC_KEYS = {"/clock": "clock", "/odom": "odom", "/tf": "tf", "/joint_states": "joint_states", "/scan": "scan",
              "/imu": "imu", "~model_states": "model_states", "~world_markers": "world_markers",
              "~scene_primitives": "scene_primitives",
              "/camera/rgb/image_raw": "rgb", "/camera/rgb/camera_info": "rgb_info",
              "/camera/rgb/image_raw/compressed": "compressed", "/camera/depth/image_raw": "depth",
              "/camera/depth/camera_info": "depth_info"}
SMALL_CAMERA = {"camera_width": 64, "camera_height": 48}
ROOT = RobotNaming("/")


class FakePublisher:
    def __init__(self, topic, subscribers):
        self.name = TOPIC_KEYS.get(topic.name, topic.name)
        self.topic = topic
        self.subscribers = subscribers

    def get_num_connections(self):
        return self.subscribers


def outputs(world, subscribed=True, naming=ROOT, **config):
    """The world's outputs and every robot's, all named by `naming`, with fake publishers (a 64x48 camera unless
    `config` says otherwise)."""
    config = SimConfig(world_path=None, **{**SMALL_CAMERA, **config})
    publisher = OutputPublisher(world_outputs(config), lambda topic: FakePublisher(topic, int(subscribed)))
    for index, robot in enumerate(world.robots()):
        publisher.add(robot_outputs(config, robot, naming, index), world.time_s)
    return publisher


@pytest.fixture
def world():
    return World(load_world(shipped_world_path("turtlebot3_world")), Pose2D(-2.0, -0.5, 0.0))


def run(world, publisher, seconds):
    counts = Counter()
    last = {}
    for _ in range(round(seconds / world.step_s)):
        world.step()
        for fake, message in publisher.collect(world):
            counts[fake.name] += 1
            last[fake.name] = message
    return counts, last


def test_rates_over_two_sim_seconds(world):
    counts, _ = run(world, outputs(world), 2.0)
    camera = {key: 60 for key in ("rgb", "rgb_info", "compressed", "depth", "depth_info")}
    assert counts == {"clock": 200, "odom": 60, "tf": 60, "joint_states": 60, "scan": 10, "imu": 200,
                      "model_states": 200, "world_markers": 4, **camera}


@pytest.mark.parametrize("clock_rate, ticks_per_second", [(100.0, 100), (0.0, 200)])
@pytest.mark.parametrize("subscribed", [True, False])
def test_the_clock_ticks_exactly_at_the_steps_that_send_clock(world, clock_rate, ticks_per_second, subscribed):
    """The loop waits for wall time only at ticks: one per /clock message, whatever the rate, with or without
    subscribers (/clock is not lazy), and none after a reset until the next message."""
    publisher = outputs(world, subscribed=subscribed, clock_rate=clock_rate)
    clock = publisher.output(ClockOutput)
    ticks, sent = [], []
    for _ in range(200):
        now_s = world.step()
        sent.append(any(fake.name == "clock" for fake, _ in publisher.collect(world)))
        ticks.append(clock.ticked(now_s))
    assert sum(ticks) == ticks_per_second
    assert ticks == sent if subscribed else not any(sent)
    publisher.reset(world.time_s)
    assert not clock.ticked(world.time_s)


def test_nothing_is_built_without_subscribers_and_lazy_outputs_are_not_read(world):
    publisher = outputs(world, subscribed=False)
    counts, _ = run(world, publisher, 1.0)
    assert counts == {}
    assert publisher.output(ScanOutput).latest is None


def test_registry_order_clock_first_and_every_output_declares_topics_and_rate(world):
    registered = outputs(world).outputs
    assert isinstance(registered[0], ClockOutput)
    assert [type(o).__name__ for o in registered] == [
        "ClockOutput", "ModelStatesOutput", "WorldMarkersOutput", "ScenePrimitivesOutput",
        "OdometryOutput", "ScanOutput", "ImuOutput",
        "CameraOutput"]
    for output in registered:
        assert isinstance(output, Output) and output.topics and output.rate_hz >= 0


def test_without_camera_parameters_each_camera_keeps_its_models_size_and_rate(world):
    camera = outputs(world, camera_width=None, camera_height=None).outputs[-1]
    assert (camera.intrinsics.width, camera.intrinsics.height, camera.rate_hz) == (1920, 1080, 30.0)
    assert camera.intrinsics.hfov_rad == 1.3439


def test_a_burger_has_no_camera_and_a_waffle_pi_camera_no_depth():
    burger = World(load_world(shipped_world_path("empty")), robot_name="turtlebot3_burger", robot_model=BURGER)
    assert "CameraOutput" not in [type(o).__name__ for o in outputs(burger).outputs]
    waffle_pi = World(load_world(shipped_world_path("empty")), robot_name="turtlebot3_waffle_pi",
                      robot_model=WAFFLE_PI)
    waffle_pi_outputs = outputs(waffle_pi, camera_width=None, camera_height=None).outputs
    assert (waffle_pi_outputs[-1].intrinsics.width, waffle_pi_outputs[-1].intrinsics.height) == (640, 480)
    topics = {topic.name for output in waffle_pi_outputs for topic in output.topics}
    assert {"/camera/rgb/image_raw", "/camera/rgb/camera_info", "/camera/rgb/image_raw/compressed"} <= topics
    assert not {t for t in topics if "depth" in t}


def test_a_namespaced_robot_publishes_in_its_namespace_with_prefixed_frames(world):
    _, last = run(world, outputs(world, naming=RobotNaming("/tb3_1/", "tb3_1")), 0.5)
    assert (last["/tb3_1/odom"].header.frame_id, last["/tb3_1/odom"].child_frame_id) == (
        "tb3_1/odom", "tb3_1/base_footprint")
    assert [(t.header.frame_id, t.child_frame_id) for t in last["tf"].transforms] == [
        ("tb3_1/odom", "tb3_1/base_footprint")]
    assert last["/tb3_1/scan"].header.frame_id == "tb3_1/base_scan"
    assert last["/tb3_1/imu"].header.frame_id == "tb3_1/base_footprint"
    assert last["/tb3_1/camera/rgb/camera_info"].header.frame_id == "tb3_1/camera_rgb_optical_frame"


def test_messages_carry_the_world_state_and_frames(world):
    world.robot.set_command(0.2, 0.0)
    publisher = outputs(world)
    _, last = run(world, publisher, 1.0)
    assert last["clock"].clock.to_sec() == pytest.approx(1.0)
    assert last["odom"].twist.twist.linear.x == pytest.approx(0.2)
    assert (last["odom"].header.frame_id, last["odom"].child_frame_id) == ("odom", "base_footprint")
    assert last["scan"].header.stamp.to_sec() == pytest.approx(1.0)
    assert last["scan"].header.frame_id == "base_scan"
    assert last["imu"].header.frame_id == "base_footprint"
    assert publisher.output(ScanOutput).latest.time_s == pytest.approx(1.0)
    assert last["model_states"].name == ["ground_plane", "ros_symbol", "turtlebot3_waffle"]


def test_latched_world_markers_and_scene_go_out_at_start_without_subscribers(world):
    pairs = outputs(world, subscribed=False).latched(world)
    assert [fake.name for fake, _ in pairs] == ["world_markers", "scene_primitives"]
    assert len(pairs[0][1].markers) > 1
    scene = json.loads(pairs[1][1].data)
    assert len(scene) == len(world.description.static_shapes)
    assert {primitive["kind"] for primitive in scene} <= {"FilledPolygon", "Polyline", "Disc"}


def test_reset_restarts_every_schedule_and_the_noise_stream(world):
    publisher = outputs(world, seed=7)
    _, first = run(world, publisher, 1.0)
    world.reset_simulation()
    publisher.reset(world.time_s)
    assert publisher.output(ScanOutput).latest is None
    counts, again = run(world, publisher, 1.0)
    assert (counts["odom"], counts["scan"], counts["imu"]) == (30, 5, 100)
    assert again["scan"].ranges == first["scan"].ranges


def test_forget_motion_hides_a_teleport_from_the_imu(world):
    publisher = outputs(world)
    run(world, publisher, 0.1)
    world.set_model_state("turtlebot3_waffle", Pose2D(0.5, 0.5, 0.0))
    world.robot.body.linearVelocity = (1.0, 0.0)
    publisher.forget_motion()
    _, last = run(world, publisher, 0.01)
    assert last["imu"].linear_acceleration.x == 0.0


def test_view_scan_reuses_a_fresh_scan_and_replaces_a_stale_one(world):
    scan = outputs(world).output(ScanOutput)
    publisher = OutputPublisher([scan], lambda topic: FakePublisher(topic, 1))
    run(world, publisher, 0.2)
    assert scan.for_view(world) is scan.latest
    world.run(1.0)
    assert scan.for_view(world).time_s == pytest.approx(world.time_s)


def frames_of(message):
    """The frame ids a message is stamped in (headers, TF parents and children, markers)."""
    frames = set()
    for part in [message, *getattr(message, "transforms", []), *getattr(message, "markers", [])]:
        header = getattr(part, "header", None)
        if header is not None and header.frame_id:
            frames.add(header.frame_id)
        if getattr(part, "child_frame_id", ""):
            frames.add(part.child_frame_id)
    return frames


def test_every_message_is_in_the_frames_its_output_declares(world):
    publisher = outputs(world)
    declared = {topic.name: set(output.frame_ids) for output in publisher.outputs for topic in output.topics}
    for _ in range(round(0.5 / world.step_s)):
        world.step()
        for fake, message in publisher.collect(world):
            assert frames_of(message) <= declared[fake.topic.name], (fake.topic.name, frames_of(message))
