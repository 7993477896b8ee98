"""Fixtures for the turtlesim core tests: a headless Qt platform, a log recorder, a factory."""
import os
import random

import pytest

os.environ.setdefault('QT_QPA_PLATFORM', 'offscreen')


class LogRecorder:
    """A LogSink that keeps (level, text) pairs."""

    def __init__(self):
        self.events = []

    def __call__(self, level, text):
        self.events.append((level, text))

    def texts(self, level=None):
        return [text for event_level, text in self.events if level in (None, event_level)]


@pytest.fixture
def log():
    return LogRecorder()


@pytest.fixture
def params():
    """Mutable parameter server stand-in for ~background_r/g/b."""
    return {}


@pytest.fixture
def make_sim(log, params):
    from turtlesim.core.simulation import TurtleSim

    def make(node_name='/turtlesim'):
        return TurtleSim(node_name, params.get, log, random.Random(7))
    return make
