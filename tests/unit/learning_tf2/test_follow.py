"""The tf2 tutorial's follower controller and carrot frames."""
import math

import pytest

from learning_tf2.follow import FIXED_CARROT_OFFSET_M, follow_command, moving_carrot_offset, yaw_quaternion


def test_target_straight_ahead_drives_without_turning():
    assert follow_command(2.0, 0.0) == (1.0, 0.0)


def test_target_to_the_left_turns_left_with_gain_4():
    command = follow_command(0.0, 2.0)
    assert command.linear == pytest.approx(1.0)
    assert command.angular == pytest.approx(4 * math.pi / 2)


def test_target_behind_turns_the_short_way_round():
    assert follow_command(-1.0, -1e-9).angular == pytest.approx(-4 * math.pi)


def test_fixed_carrot_is_two_metres_left():
    assert FIXED_CARROT_OFFSET_M == (0.0, 2.0)


@pytest.mark.parametrize("t, expected", [(0.0, (0.0, 10.0)), (0.5, (10.0, 0.0)), (1.0, (0.0, -10.0))])
def test_moving_carrot_circles_every_two_seconds(t, expected):
    assert moving_carrot_offset(t) == pytest.approx(expected, abs=1e-9)


def test_yaw_quaternion_is_unit_and_about_z():
    x, y, z, w = yaw_quaternion(1.0)
    assert (x, y) == (0.0, 0.0)
    assert math.hypot(z, w) == pytest.approx(1.0)
    assert 2 * math.atan2(z, w) == pytest.approx(1.0)
