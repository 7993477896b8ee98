"""Fixtures for the turtlebot3_description integration tests."""
import re

import pytest

from roslab import wait_until

TRANSFORM = re.compile(r"- Translation: \[([^\]]+)\]\s*\n- Rotation: in Quaternion \[([^\]]+)\]")


def numbers(text):
    return tuple(float(value) for value in text.split(","))


@pytest.fixture
def tf_echo(ros_master):
    """tf_echo(target, source): run `rosrun tf tf_echo target source` on the module's master until it prints a
    transform, as a user would read it; returns (translation xyz, quaternion xyzw), three decimals each."""

    def echo(target, source, timeout_s=30.0):
        process = ros_master.rosrun("tf", "tf_echo", target, source)
        try:
            match = wait_until(lambda: TRANSFORM.search(process.output()), timeout_s,
                               "tf_echo {} {} to print a transform".format(target, source))
        finally:
            process.stop()
        return numbers(match.group(1)), numbers(match.group(2))

    return echo
