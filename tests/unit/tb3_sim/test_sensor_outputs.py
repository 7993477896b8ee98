"""SensorOutputs: which messages go out after each step, at Gazebo's rates in sim time (fake publishers)."""
from collections import Counter

import pytest

from tb3_sim.geometry import Pose2D
from tb3_sim.sensor_outputs import Publishers, SensorOutputs
from tb3_sim.world import World
from tb3_sim.world_file import load_world, shipped_world_path


class FakePublisher:
    def __init__(self, name, subscribers):
        self.name = name
        self.subscribers = subscribers

    def get_num_connections(self):
        return self.subscribers


def outputs(subscribed=True):
    return SensorOutputs(Publishers(*(FakePublisher(name, int(subscribed)) for name in Publishers._fields)))


@pytest.fixture
def world():
    return World(load_world(shipped_world_path("turtlebot3_world")), Pose2D(-2.0, -0.5, 0.0))


def run(world, sensor_outputs, seconds):
    counts = Counter()
    last = {}
    for _ in range(round(seconds / world.step_s)):
        world.step()
        for publisher, message in sensor_outputs.collect(world):
            counts[publisher.name] += 1
            last[publisher.name] = message
    return counts, last


def test_rates_over_two_sim_seconds(world):
    counts, _ = run(world, outputs(), 2.0)
    assert counts == {"clock": 400, "odom": 60, "tf": 60, "joint_states": 60, "scan": 10, "imu": 200,
                      "model_states": 200}


def test_lazy_topics_stay_quiet_without_subscribers(world):
    counts, _ = run(world, outputs(subscribed=False), 1.0)
    assert set(counts) == {"clock", "odom", "tf", "joint_states"}


def test_messages_carry_the_world_state(world):
    world.robot.set_command(0.2, 0.0)
    sensor_outputs = outputs()
    _, last = run(world, sensor_outputs, 1.0)
    assert last["clock"].clock.to_sec() == pytest.approx(1.0)
    assert last["odom"].twist.twist.linear.x == pytest.approx(0.2)
    assert last["scan"].header.stamp.to_sec() == pytest.approx(1.0)
    assert sensor_outputs.latest_scan.time_s == pytest.approx(1.0)
    assert last["model_states"].name == ["ground_plane", "ros_symbol", "turtlebot3_waffle"]


def test_restart_after_a_clock_rewind(world):
    sensor_outputs = outputs()
    run(world, sensor_outputs, 1.0)
    world.reset_simulation()
    sensor_outputs.restart(world.time_s)
    counts, _ = run(world, sensor_outputs, 1.0)
    assert (counts["odom"], counts["scan"]) == (30, 5)


def test_view_scan_reuses_a_fresh_scan_and_replaces_a_stale_one(world):
    sensor_outputs = outputs()
    run(world, sensor_outputs, 0.2)
    assert sensor_outputs.scan_for_view(world) is sensor_outputs.latest_scan
    world.run(1.0)
    assert sensor_outputs.scan_for_view(world).time_s == pytest.approx(world.time_s)
