"""Fixtures for the tb3_sim unit tests."""
from contextlib import contextmanager

import pytest


class FakeSim:
    """What GazeboApi and BoxTool need from the ROS node, without ROS: the world behind a (trivial) lock, the
    pause flag, resets, a count of teleports and the world changes reported for the ground-truth channel."""

    rendering_enabled = False

    def __init__(self, world):
        self.world = world
        self.paused = False
        self.teleports = 0
        self.changes = []

    @contextmanager
    def locked_world(self):
        yield self.world

    def teleported(self):
        self.teleports += 1

    def world_changed(self, what, detail=""):
        self.changes.append((what, detail))

    def pause(self):
        self.paused = True

    def unpause(self):
        self.paused = False

    def reset_world(self):
        self.world.reset_world()

    def reset_simulation(self):
        self.world.reset_simulation()


@pytest.fixture
def fake_sim():
    """FakeSim(world): a stand-in for tb3_sim.ros.node.SimNode around `world`."""
    return FakeSim
