"""The output seam: every periodic output registered once, published at Gazebo's rates in sim time, lazy ones
quiet without subscribers, all restarted by a reset (fake publishers, no master)."""
from collections import Counter

import pytest

from tb3_sim.core.geometry import Pose2D
from tb3_sim.core.world import World
from tb3_sim.core.world_file import load_world, shipped_world_path
from tb3_sim.ros.config import SimConfig
from tb3_sim.ros.outputs import Output, OutputPublisher, registered_outputs
from tb3_sim.ros.outputs.clock import ClockOutput
from tb3_sim.ros.outputs.scan import ScanOutput

TOPIC_KEYS = {"/clock": "clock", "odom": "odom", "/tf": "tf", "joint_states": "joint_states", "scan": "scan",
              "imu": "imu", "~model_states": "model_states", "~world_markers": "world_markers",
              "/camera/rgb/image_raw": "rgb", "/camera/rgb/camera_info": "rgb_info",
              "/camera/rgb/image_raw/compressed": "compressed", "/camera/depth/image_raw": "depth",
              "/camera/depth/camera_info": "depth_info"}
SMALL_CAMERA = {"camera_width": 64, "camera_height": 48}


class FakePublisher:
    def __init__(self, topic, subscribers):
        self.name = TOPIC_KEYS[topic.name]
        self.topic = topic
        self.subscribers = subscribers

    def get_num_connections(self):
        return self.subscribers


def outputs(subscribed=True, **config):
    """Every registered output with fake publishers (a 64x48 camera unless `config` says otherwise)."""
    config = {**SMALL_CAMERA, **config}
    return OutputPublisher(registered_outputs(SimConfig(world_path=None, **config)),
                           lambda topic: FakePublisher(topic, int(subscribed)))


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
    counts, _ = run(world, outputs(), 2.0)
    camera = {key: 60 for key in ("rgb", "rgb_info", "compressed", "depth", "depth_info")}
    assert counts == {"clock": 400, "odom": 60, "tf": 60, "joint_states": 60, "scan": 10, "imu": 200,
                      "model_states": 200, "world_markers": 4, **camera}


def test_nothing_is_built_without_subscribers_and_lazy_outputs_are_not_read(world):
    publisher = outputs(subscribed=False)
    counts, _ = run(world, publisher, 1.0)
    assert counts == {}
    assert publisher.output(ScanOutput).latest is None


def test_registry_order_clock_first_and_every_output_declares_topics_and_rate():
    registered = registered_outputs(SimConfig(world_path=None, **SMALL_CAMERA))
    assert isinstance(registered[0], ClockOutput)
    assert [type(o).__name__ for o in registered] == [
        "ClockOutput", "OdometryOutput", "ScanOutput", "ImuOutput", "ModelStatesOutput", "WorldMarkersOutput",
        "CameraOutput"]
    for output in registered:
        assert isinstance(output, Output) and output.topics and output.rate_hz >= 0


def test_messages_carry_the_world_state_and_frames(world):
    world.robot.set_command(0.2, 0.0)
    publisher = outputs()
    _, last = run(world, publisher, 1.0)
    assert last["clock"].clock.to_sec() == pytest.approx(1.0)
    assert last["odom"].twist.twist.linear.x == pytest.approx(0.2)
    assert (last["odom"].header.frame_id, last["odom"].child_frame_id) == ("odom", "base_footprint")
    assert last["scan"].header.stamp.to_sec() == pytest.approx(1.0)
    assert last["scan"].header.frame_id == "base_scan"
    assert last["imu"].header.frame_id == "base_footprint"
    assert publisher.output(ScanOutput).latest.time_s == pytest.approx(1.0)
    assert last["model_states"].name == ["ground_plane", "ros_symbol", "turtlebot3_waffle"]


def test_latched_world_markers_go_out_at_start_without_subscribers(world):
    pairs = outputs(subscribed=False).latched(world)
    assert [fake.name for fake, _ in pairs] == ["world_markers"]
    assert len(pairs[0][1].markers) > 1


def test_reset_restarts_every_schedule_and_the_noise_stream(world):
    publisher = outputs(seed=7)
    _, first = run(world, publisher, 1.0)
    world.reset_simulation()
    publisher.reset(world.time_s)
    assert publisher.output(ScanOutput).latest is None
    counts, again = run(world, publisher, 1.0)
    assert (counts["odom"], counts["scan"], counts["imu"]) == (30, 5, 100)
    assert again["scan"].ranges == first["scan"].ranges


def test_forget_motion_hides_a_teleport_from_the_imu(world):
    publisher = outputs()
    run(world, publisher, 0.1)
    world.set_model_state("turtlebot3_waffle", Pose2D(0.5, 0.5, 0.0))
    world.robot.body.linearVelocity = (1.0, 0.0)
    publisher.forget_motion()
    _, last = run(world, publisher, 0.01)
    assert last["imu"].linear_acceleration.x == 0.0


def test_view_scan_reuses_a_fresh_scan_and_replaces_a_stale_one(world):
    scan = outputs().output(ScanOutput)
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
    publisher = outputs()
    declared = {topic.name: set(output.frame_ids) for output in publisher.outputs for topic in output.topics}
    for _ in range(round(0.5 / world.step_s)):
        world.step()
        for fake, message in publisher.collect(world):
            assert frames_of(message) <= declared[fake.topic.name], (fake.topic.name, frames_of(message))
