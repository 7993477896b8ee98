"""The /scan helper: closest object ahead on Gazebo's TurtleBot3 LiDAR layout (index 0 ahead, CCW)."""
import math
import random
import statistics

import pytest

from tb3_client.scan_ahead import arc_indices, beam_angle_deg, closest_ahead

INCREMENT = 6.28319 / 359
INF = float("inf")


def scan(fill=INF, **readings):
    ranges = [fill] * 360
    for index, value in readings.items():
        ranges[int(index.lstrip("i"))] = value
    return ranges


def test_arc_covers_20_degrees_either_side_and_wraps():
    arc = arc_indices(360, 0.0, INCREMENT)
    assert 0 in arc and 19 in arc and 340 in arc
    assert 21 not in arc and 338 not in arc
    assert all(abs(beam_angle_deg(i, 0.0, INCREMENT)) <= 20.0 for i in arc)


def test_nothing_seen_is_none():
    assert closest_ahead(scan(), 0.0, INCREMENT, 0.12) is None


def test_object_straight_ahead():
    ranges = scan(**{"i0": 1.0, "i1": 1.0, "i359": 1.0})
    found = closest_ahead(ranges, 0.0, INCREMENT, 0.12)
    assert found.distance == pytest.approx(1.0)
    assert abs(found.angle_deg) < 1.1


def test_object_to_the_right_has_negative_angle():
    ranges = scan(**{"i349": 0.8, "i350": 0.8, "i351": 0.8})
    found = closest_ahead(ranges, 0.0, INCREMENT, 0.12)
    assert found.distance == pytest.approx(0.8)
    assert beam_angle_deg(349, 0.0, INCREMENT) <= found.angle_deg <= beam_angle_deg(351, 0.0, INCREMENT)
    assert -11 < found.angle_deg < -8


def test_objects_outside_the_arc_are_ignored():
    ranges = scan(**{"i90": 0.3, "i180": 0.3, "i270": 0.3, "i0": 2.0, "i1": 2.0})
    assert closest_ahead(ranges, 0.0, INCREMENT, 0.12).distance == pytest.approx(2.0)


def test_nan_and_below_range_min_are_ignored():
    ranges = scan(**{"i0": float("nan"), "i1": 0.05, "i2": 1.5, "i3": 1.5, "i4": 1.5})
    assert closest_ahead(ranges, 0.0, INCREMENT, 0.12).distance == pytest.approx(1.5)


def test_a_single_noisy_low_beam_does_not_win():
    ranges = scan(**{"i357": 1.0, "i358": 1.0, "i359": 0.9, "i0": 1.0, "i1": 1.0})
    assert closest_ahead(ranges, 0.0, INCREMENT, 0.12).distance == pytest.approx(1.0)


def test_real_driver_layout_with_negative_angle_min():
    increment = 2 * math.pi / 360
    ranges = [INF] * 360
    ranges[180] = ranges[181] = ranges[179] = 0.7   # angle_min = -pi: index 180 is straight ahead
    found = closest_ahead(ranges, -math.pi, increment, 0.12)
    assert found.distance == pytest.approx(0.7)
    assert abs(found.angle_deg) < 1.5


def test_gazebo_noise_on_a_wall_ahead_biases_the_distance_by_less_than_5_mm():
    """The stopping distance of the approach servers is this reading: a flat wall 0.4 m ahead, sigma 0.01 m."""
    rng = random.Random(1)
    increment = 2 * math.pi / 360
    readings = []
    for _ in range(400):
        ranges = [0.4 / math.cos(i * increment) + rng.gauss(0.0, 0.01) if math.cos(i * increment) > 0.3 else INF
                  for i in range(360)]
        readings.append(closest_ahead(ranges, 0.0, increment, 0.12).distance)
    assert statistics.mean(readings) == pytest.approx(0.4, abs=0.005)


def test_an_object_a_few_beams_wide_before_a_farther_wall_is_seen():
    ranges = scan(fill=2.0, **{"i358": 0.6, "i359": 0.6, "i0": 0.6, "i1": 0.6, "i2": 0.6})
    assert closest_ahead(ranges, 0.0, INCREMENT, 0.12).distance == pytest.approx(0.6)
