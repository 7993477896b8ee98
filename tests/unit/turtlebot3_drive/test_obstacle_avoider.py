"""turtlebot3_drive's decisions: which beams it reads, its thresholds, speeds, escape angle and state machine."""
import math

import pytest

from turtlebot3_gazebo.obstacle_avoider import (
    ESCAPE_ANGLE_RAD,
    FORWARD,
    TURN_LEFT,
    TURN_RIGHT,
    Command,
    DriveError,
    ObstacleAvoider,
    Ranges,
    State,
    angle_between,
    heading_from_quaternion,
    ranges_from_scan,
)

INF = math.inf
RANGE_MAX = 3.5
CLEAR = Ranges(RANGE_MAX, RANGE_MAX, RANGE_MAX)


def run(avoider, ranges, heading, ticks):
    """The commands of `ticks` consecutive steps with the same readings (None where nothing is published)."""
    return [avoider.step(ranges, heading) for _ in range(ticks)]


def scan(**readings):
    """360 ranges of +inf (nothing seen), with the given readings, e.g. scan(i0=1.0, i30=0.5)."""
    ranges = [INF] * 360
    for index, value in readings.items():
        ranges[int(index[1:])] = value
    return ranges


# ---- the three beams


def test_reads_beams_0_30_and_330_as_ahead_left_right():
    ranges = scan(i0=1.0, i30=2.0, i330=3.0, i1=0.2, i29=0.2, i31=0.2, i329=0.2, i331=0.2, i90=0.2, i270=0.2)
    assert ranges_from_scan(ranges, RANGE_MAX) == Ranges(center=1.0, left=2.0, right=3.0)


def test_nothing_seen_counts_as_range_max():
    assert ranges_from_scan(scan(), RANGE_MAX) == CLEAR
    assert ranges_from_scan(scan(i0=-INF), RANGE_MAX).center == RANGE_MAX


def test_nan_is_kept_and_decides_nothing():
    ranges = ranges_from_scan(scan(i0=math.nan), RANGE_MAX)
    assert math.isnan(ranges.center)
    avoider = ObstacleAvoider()
    assert run(avoider, ranges, 0.0, 3) == [None, None, None]
    assert avoider.state is State.GET_DIRECTION


def test_a_scan_too_short_for_beam_330_is_refused_clearly():
    with pytest.raises(DriveError, match=r"the scan has 330 ranges.* needs at least 331 \(the LDS-01 gives 360\)"):
        ranges_from_scan([1.0] * 330, RANGE_MAX)


# ---- decisions


def test_clear_ahead_drives_forward_every_other_tick():
    avoider = ObstacleAvoider()
    assert run(avoider, CLEAR, 0.0, 4) == [None, FORWARD, None, FORWARD]
    assert FORWARD == Command(linear=0.3, angular=0.0)


@pytest.mark.parametrize("center", [0.69, 0.3, 0.12])
def test_obstacle_ahead_turns_right_on_the_spot(center):
    avoider = ObstacleAvoider()
    assert run(avoider, Ranges(center, RANGE_MAX, RANGE_MAX), 0.0, 3) == [None, TURN_RIGHT, TURN_RIGHT]
    assert TURN_RIGHT == Command(linear=0.0, angular=-1.5)


def test_obstacle_ahead_turns_right_even_when_only_the_right_is_open():
    avoider = ObstacleAvoider()
    assert run(avoider, Ranges(0.5, 0.3, RANGE_MAX), 0.0, 2) == [None, TURN_RIGHT]


def test_obstacle_on_the_left_turns_right():
    avoider = ObstacleAvoider()
    assert run(avoider, Ranges(RANGE_MAX, 0.59, RANGE_MAX), 0.0, 2) == [None, TURN_RIGHT]


def test_obstacle_on_the_right_turns_left():
    avoider = ObstacleAvoider()
    assert run(avoider, Ranges(RANGE_MAX, RANGE_MAX, 0.59), 0.0, 2) == [None, TURN_LEFT]
    assert TURN_LEFT == Command(linear=0.0, angular=1.5)


def test_obstacles_on_both_sides_turn_right():
    avoider = ObstacleAvoider()
    assert run(avoider, Ranges(RANGE_MAX, 0.4, 0.4), 0.0, 2) == [None, TURN_RIGHT]


@pytest.mark.parametrize("ranges", [Ranges(0.71, 0.61, 0.61), Ranges(0.71, 0.6, 0.6)])
def test_just_outside_the_thresholds_drives_forward(ranges):
    assert run(ObstacleAvoider(), ranges, 0.0, 2) == [None, FORWARD]


def test_exactly_the_forward_threshold_decides_nothing():
    avoider = ObstacleAvoider()
    assert run(avoider, Ranges(0.7, RANGE_MAX, RANGE_MAX), 0.0, 3) == [None, None, None]


def test_a_new_reading_is_not_used_until_the_next_decision():
    avoider = ObstacleAvoider()
    assert avoider.step(CLEAR, 0.0) is None
    assert avoider.step(Ranges(0.2, 0.2, 0.2), 0.0) == FORWARD
    assert run(avoider, Ranges(0.2, 0.2, 0.2), 0.0, 2) == [None, TURN_RIGHT]


# ---- turns and the escape angle


def turn_until_done(avoider, ranges, start, direction, step_rad=math.radians(1.0), limit=400):
    """Step while the heading moves by `step_rad` per tick in `direction` (+1 left, -1 right); the total turn
    (rad) when the avoider stops commanding the turn."""
    heading = start
    for tick in range(limit):
        command = avoider.step(ranges, heading)
        if command is None and tick > 0:
            return angle_between(heading, start)
        heading = math.remainder(heading + direction * step_rad, 2.0 * math.pi)
    raise AssertionError("the turn never ended")


def test_right_turn_ends_after_30_degrees_then_decides_again():
    avoider = ObstacleAvoider()
    ahead_blocked = Ranges(0.5, RANGE_MAX, RANGE_MAX)
    avoider.step(ahead_blocked, 0.0)
    turned = turn_until_done(avoider, ahead_blocked, 0.0, -1)
    assert turned == pytest.approx(ESCAPE_ANGLE_RAD, abs=math.radians(1.0))
    assert turned >= ESCAPE_ANGLE_RAD
    assert avoider.state is State.GET_DIRECTION
    assert run(avoider, CLEAR, -turned, 2) == [None, FORWARD]


def test_left_turn_ends_after_30_degrees():
    avoider = ObstacleAvoider()
    right_blocked = Ranges(RANGE_MAX, RANGE_MAX, 0.3)
    avoider.step(right_blocked, 1.0)
    assert turn_until_done(avoider, right_blocked, 1.0, +1) == pytest.approx(math.radians(30.0), abs=0.02)


def test_turn_continues_before_the_escape_angle_whatever_the_ranges():
    avoider = ObstacleAvoider()
    avoider.step(Ranges(0.5, RANGE_MAX, RANGE_MAX), 0.0)
    assert avoider.step(CLEAR, -math.radians(29.0)) == TURN_RIGHT
    assert avoider.step(CLEAR, -math.radians(30.5)) is None


@pytest.mark.parametrize("start, ranges, direction", [
    (math.radians(170.0), Ranges(RANGE_MAX, RANGE_MAX, 0.3), +1),   # left turn through +pi
    (math.radians(-170.0), Ranges(0.5, RANGE_MAX, RANGE_MAX), -1),  # right turn through -pi
])
def test_turn_across_plus_minus_pi_still_lasts_30_degrees(start, ranges, direction):
    avoider = ObstacleAvoider()
    avoider.step(ranges, start)
    assert turn_until_done(avoider, ranges, start, direction) == pytest.approx(math.radians(30.0), abs=0.02)


def test_still_blocked_after_a_turn_turns_again_from_the_new_heading():
    avoider = ObstacleAvoider()
    blocked = Ranges(0.5, RANGE_MAX, RANGE_MAX)
    avoider.step(blocked, 0.0)
    turned = turn_until_done(avoider, blocked, 0.0, -1)
    assert avoider.step(blocked, -turned) is None
    assert avoider.turn_start_heading == -turned
    assert avoider.step(blocked, -turned) == TURN_RIGHT


# ---- heading


@pytest.mark.parametrize("yaw", [0.0, 0.5, -1.2, math.pi - 1e-9, -math.pi / 2])
def test_heading_from_a_yaw_quaternion(yaw):
    assert heading_from_quaternion(0.0, 0.0, math.sin(yaw / 2), math.cos(yaw / 2)) == pytest.approx(yaw)


@pytest.mark.parametrize("a, b, expected", [(0.1, -0.1, 0.2), (3.1, -3.1, 2 * math.pi - 6.2),
                                            (-3.0, 3.0, 2 * math.pi - 6.0), (1.0, 1.0, 0.0)])
def test_angle_between_headings_wraps(a, b, expected):
    assert angle_between(a, b) == pytest.approx(expected)
