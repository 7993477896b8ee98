"""Tutorial helpers: the draw_square state machine and the teleop key table."""
import pytest

from roslab.turtle_driver import drive
from turtlesim.core.constants import WORLD_CENTRE
from turtlesim.core.draw_square import SquareDriver, SquareState
from turtlesim.core.log import LogLevel
from turtlesim.core.teleop_keys import BANNER, KEY_QUIT, command_for_key
from turtlesim.core.turtle import Turtle


def test_draw_square_corners_and_logs(log):
    driver = SquareDriver(log)
    corners = []

    def step(pose):
        state = driver.state
        command = driver.on_timer(pose)
        if state is SquareState.STOP_FORWARD and driver.state is SquareState.TURN:
            corners.append((pose.x, pose.y))
        return command

    drive(Turtle(WORLD_CENTRE, WORLD_CENTRE, 0.0), step, 2500)
    assert driver.on_timer(None) is None
    expected = [(7.544, 5.544), (7.544, 7.544), (5.544, 7.544), (5.544, 5.544)]
    assert len(corners) >= 4
    for (x, y), (expected_x, expected_y) in zip(corners, expected):
        assert abs(x - expected_x) < 0.1 and abs(y - expected_y) < 0.1
    texts = log.texts(LogLevel.INFO)
    assert texts[0] == 'New goal [7.544445 5.544445, 0.000000]'
    assert texts[1] == 'Reached goal'
    assert texts[2].startswith('New goal [7.4')


def test_draw_square_waits_for_a_pose(log):
    assert SquareDriver(log).on_timer(None) is None
    assert log.events == []


@pytest.mark.parametrize('key, command', [
    (0x41, (2.0, 0.0)), (0x42, (-2.0, 0.0)), (0x44, (0.0, 2.0)), (0x43, (0.0, -2.0)),
    (ord('A'), (2.0, 0.0)), (0x1B, None), (ord('['), None), (ord('x'), None), (KEY_QUIT, None),
])
def test_teleop_key_table(key, command):
    assert command_for_key(key) == command


def test_teleop_scales_and_banner():
    assert command_for_key(0x41, 0.5, 3.0) == (0.5, 0.0)
    assert command_for_key(0x44, 0.5, 3.0) == (0.0, 3.0)
    assert BANNER[2] == "Use arrow keys to move the turtle. 'q' to quit."
