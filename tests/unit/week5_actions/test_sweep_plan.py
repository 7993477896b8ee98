"""CameraSweep goals: the accepted ranges, the refusals and their texts, the capture angles and time limit."""
import math

import pytest

from week5_actions.sweep_plan import (
    DEFAULT_ANGULAR_SPEED_RADPS,
    MAX_IMAGE_COUNT,
    InvalidGoal,
    SweepError,
    SweepFailed,
    SweepPlan,
    plan_sweep,
)


def test_the_course_goal_becomes_a_plan():
    assert plan_sweep(90.0, 4) == SweepPlan(90.0, 4, DEFAULT_ANGULAR_SPEED_RADPS)


@pytest.mark.parametrize("angle, count", [(0.001, 1), (180.0, 1), (180.0, MAX_IMAGE_COUNT), (1, 50), (45.5, 7)])
def test_edges_of_the_accepted_ranges(angle, count):
    assert plan_sweep(angle, count).image_count == count


@pytest.mark.parametrize("count, why", [
    (0, "image_count 0 is not in 1..50: there must be at least one image"),
    (-3, "image_count -3 is not in 1..50: there must be at least one image"),
    (51, "image_count 51 is not in 1..50: that is too many images, the maximum is 50"),
    (2 ** 31 - 1, "image_count 2147483647 is not in 1..50: that is too many images, the maximum is 50"),
])
def test_image_counts_outside_1_to_50_are_refused(count, why):
    with pytest.raises(InvalidGoal) as refused:
        plan_sweep(90.0, count)
    assert str(refused.value) == why


@pytest.mark.parametrize("angle", [0.0, -90.0, -0.0, 180.01, 360.0, 1e30])
def test_sweep_angles_outside_0_to_180_are_refused(angle):
    with pytest.raises(InvalidGoal, match=r"^sweep_angle .* degrees is not in \(0, 180\]: the robot sweeps "
                                          r"anticlockwise, by at most 180 degrees$"):
        plan_sweep(angle, 4)


@pytest.mark.parametrize("angle", [math.nan, math.inf, -math.inf])
def test_non_finite_angles_are_refused(angle):
    with pytest.raises(InvalidGoal, match="is not a finite number of degrees"):
        plan_sweep(angle, 4)


def test_every_problem_is_named():
    with pytest.raises(InvalidGoal) as refused:
        plan_sweep(-10.0, 0)
    assert str(refused.value).startswith("sweep_angle -10 degrees is not in (0, 180]")
    assert "; image_count 0 is not in 1..50" in str(refused.value)


def test_errors_share_one_root():
    assert issubclass(InvalidGoal, SweepError) and issubclass(SweepFailed, SweepError)


def test_captures_are_spread_over_the_sweep_ending_at_its_end():
    plan = plan_sweep(90.0, 4)
    assert plan.capture_angles_deg == (22.5, 45.0, 67.5, 90.0)
    assert plan.step_deg == 22.5


def test_one_image_is_taken_at_the_end():
    assert plan_sweep(30.0, 1).capture_angles_deg == (30.0,)


@pytest.mark.parametrize("angle, count", [(0.1, 3), (179.9, 49), (1e-6, 50), (33.3, 7)])
def test_the_last_capture_angle_is_the_sweep_angle(angle, count):
    angles = plan_sweep(angle, count).capture_angles_deg
    assert len(angles) == count and angles[-1] == pytest.approx(angle, rel=1e-12)
    assert all(a < b for a, b in zip(angles, angles[1:]))


def test_duration_and_time_limit():
    plan = plan_sweep(90.0, 4, angular_speed_radps=0.2)
    assert plan.ideal_duration_s == pytest.approx(math.pi / 2 / 0.2)
    assert plan.time_limit_s == pytest.approx(2 * plan.ideal_duration_s + 5.0)
