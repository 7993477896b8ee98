"""The Gazebo diff-drive semantics: ramp, snap rule, no timeout, no clamp, validation, wheel angles."""

import math

import pytest

from tb3_sim.core.diff_drive import DiffDrive, validate_command
from tb3_sim.core.errors import InvalidCommandError
from tb3_sim.core.turtlebot3 import WAFFLE, WHEEL_RADIUS_M

STEP_S = 0.005


def run(drive, start_s, duration_s):
    """Call the drive's hooks as the world does for `duration_s`; return the end time."""
    steps = round(duration_s / STEP_S)
    for i in range(1, steps + 1):
        drive.update(start_s + i * STEP_S)
        drive.advance_wheels(STEP_S)
    return start_s + steps * STEP_S


def test_ramp_from_rest_reaches_a_tenth_after_a_tenth_of_a_second():
    drive = DiffDrive()
    drive.set_command(0.26, 0.0)
    run(drive, 0.0, 0.1)
    assert drive.velocity[0] == pytest.approx(0.1, abs=1e-9)


def test_ramp_reaches_the_target_and_stays():
    drive = DiffDrive()
    drive.set_command(0.26, 0.0)
    end = run(drive, 0.0, 0.3)
    assert drive.velocity == pytest.approx((0.26, 0.0))
    run(drive, end, 10.0)
    assert drive.velocity == pytest.approx((0.26, 0.0)), "no timeout: the command is held"


def test_updates_happen_at_30_hz_only():
    drive = DiffDrive()
    drive.set_command(0.26, 0.0)
    drive.update(0.03)
    assert drive.velocity[0] == 0.0
    drive.update(1.0 / 30.0)
    assert drive.velocity[0] == pytest.approx(1.0 / 30.0)


def test_small_change_is_applied_at_once():
    drive = DiffDrive()
    drive.set_command(0.005, 0.0)
    drive.update(1.0 / 30.0)
    assert drive.velocity[0] == 0.005


def test_no_clamp_by_default_and_optional_clamp():
    fast = DiffDrive()
    fast.set_command(1.0, 3.0)
    run(fast, 0.0, 2.0)
    assert fast.velocity == pytest.approx((1.0, 3.0))
    clamped = DiffDrive(limits=(WAFFLE.max_linear_mps, WAFFLE.max_angular_radps))
    clamped.set_command(1.0, 3.0)
    run(clamped, 0.0, 2.0)
    assert clamped.velocity == pytest.approx((0.26, 1.82))


def test_turning_in_place_turns_the_wheels_opposite_ways():
    drive = DiffDrive()
    drive.set_command(0.0, 1.0)
    run(drive, 0.0, 1.0)
    left, right = drive.wheel_angles
    assert left == pytest.approx(-right)
    rim = WAFFLE.wheel_separation_m / 2.0
    assert right > 0.0 and right == pytest.approx(rim / WHEEL_RADIUS_M * 1.0, rel=0.15)


def test_wheel_angle_is_distance_over_radius():
    drive = DiffDrive(acceleration_mps2=0.0)
    drive.set_command(0.2, 0.0)
    drive.update(1.0 / 30.0)
    run(drive, 1.0 / 30.0, 1.0)
    assert drive.wheel_angles == pytest.approx((0.2 / WHEEL_RADIUS_M,) * 2, rel=1e-6)


def test_reset_zeroes_command_speed_and_angles():
    drive = DiffDrive()
    drive.set_command(0.2, 0.5)
    end = run(drive, 0.0, 1.0)
    drive.reset(end)
    run(drive, end, 1.0)
    assert drive.command == (0.0, 0.0)
    assert drive.velocity == (0.0, 0.0) and drive.wheel_angles == (0.0, 0.0)


@pytest.mark.parametrize("linear, angular, field", [
    (math.nan, 0.0, "linear.x"), (math.inf, 0.0, "linear.x"), (0.0, -math.inf, "angular.z"),
    (11.0, 0.0, "linear.x"), (0.0, 31.0, "angular.z"),
])
def test_invalid_commands_are_refused_with_a_reason(linear, angular, field):
    reason = validate_command(linear, angular)
    assert reason is not None and field in reason
    drive = DiffDrive()
    drive.set_command(0.1, 0.2)
    with pytest.raises(InvalidCommandError, match=field.replace(".", r"\.")):
        drive.set_command(linear, angular)
    assert drive.command == (0.1, 0.2), "an invalid command leaves the previous one in force"


def test_valid_commands_have_no_reason():
    assert validate_command(0.26, -1.82) is None
    assert validate_command(5.0, 0.0) is None
