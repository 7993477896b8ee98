"""Yaw from quaternions and the unwrapped angle turned, also through the +-180 degree seam."""
import math

import pytest

from week5_actions.heading import HeadingTracker, wrap_angle, yaw_from_quaternion


@pytest.mark.parametrize("yaw", [0.0, 0.3, -1.2, math.pi / 2, 3.0, -3.0])
def test_yaw_of_a_pure_z_rotation(yaw):
    assert yaw_from_quaternion(0.0, 0.0, math.sin(yaw / 2), math.cos(yaw / 2)) == pytest.approx(yaw)


@pytest.mark.parametrize("angle, wrapped", [(0.0, 0.0), (math.pi, math.pi), (-math.pi, math.pi),
                                            (3 * math.pi / 2, -math.pi / 2), (-5.0, -5.0 + 2 * math.pi)])
def test_wrap_angle(angle, wrapped):
    assert wrap_angle(angle) == pytest.approx(wrapped)


def headings(start_deg, step_deg, steps):
    """Yaws (radians, wrapped as /odom reports them) of a robot turning by step_deg each step."""
    return [wrap_angle(math.radians(start_deg + step_deg * k)) for k in range(1, steps + 1)]


@pytest.mark.parametrize("start_deg", [0.0, 170.0, -175.0, 90.0])
def test_an_anticlockwise_turn_is_unwrapped(start_deg):
    tracker = HeadingTracker(math.radians(start_deg))
    for yaw in headings(start_deg, 0.8, 500):     # 400 degrees, crossing the seam at least once
        turned = tracker.update(yaw)
    assert turned == pytest.approx(400.0)
    assert tracker.turned_deg == turned


def test_a_clockwise_turn_counts_negative():
    tracker = HeadingTracker(math.radians(-170.0))
    for yaw in headings(-170.0, -1.5, 40):
        tracker.update(yaw)
    assert tracker.turned_deg == pytest.approx(-60.0)


def test_standing_still_turns_nothing():
    tracker = HeadingTracker(2.0)
    assert [tracker.update(2.0) for _ in range(3)] == [0.0, 0.0, 0.0]
