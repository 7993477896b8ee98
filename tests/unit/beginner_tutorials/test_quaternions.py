"""Roll/pitch/yaw <-> quaternion through tf.transformations, and the demo's arguments."""
import math

import pytest

from beginner_tutorials.errors import UsageError
from beginner_tutorials.quaternions import (
    DEFAULT_ANGLES,
    EulerAngles,
    Quaternion,
    parse_angles,
    same_rotation,
    to_euler,
    to_quaternion,
)

HALF_SQRT2 = math.sqrt(0.5)


@pytest.mark.parametrize("angles, quaternion", [
    (EulerAngles(0.0, 0.0, 0.0), Quaternion(0.0, 0.0, 0.0, 1.0)),
    (EulerAngles(0.0, 0.0, math.pi / 2), Quaternion(0.0, 0.0, HALF_SQRT2, HALF_SQRT2)),
    (EulerAngles(math.pi / 2, 0.0, 0.0), Quaternion(HALF_SQRT2, 0.0, 0.0, HALF_SQRT2)),
    (EulerAngles(0.0, math.pi / 2, 0.0), Quaternion(0.0, HALF_SQRT2, 0.0, HALF_SQRT2)),
    (EulerAngles(0.0, 0.0, math.pi), Quaternion(0.0, 0.0, 1.0, 0.0)),
])
def test_known_quaternions(angles, quaternion):
    assert to_quaternion(angles) == pytest.approx(quaternion, abs=1e-12)


@pytest.mark.parametrize("angles", [EulerAngles(0.1, -0.2, 0.3), EulerAngles(-3.0, 1.2, 2.5), DEFAULT_ANGLES])
def test_round_trip_inside_the_principal_ranges_gives_the_same_numbers(angles):
    assert to_euler(to_quaternion(angles)) == pytest.approx(angles, abs=1e-12)


def test_pitch_beyond_a_right_angle_comes_back_as_an_equivalent_rotation():
    angles = EulerAngles(0.0, 2.0, 0.0)
    back = to_euler(to_quaternion(angles))
    assert back != pytest.approx(angles)
    assert abs(back.pitch) <= math.pi / 2
    assert same_rotation(to_quaternion(angles), to_quaternion(back))


def test_quaternions_are_unit_length():
    quaternion = to_quaternion(EulerAngles(0.7, -0.4, 2.9))
    assert math.fsum(value * value for value in quaternion) == pytest.approx(1.0)


def test_same_rotation_accepts_the_negated_quaternion_only():
    quaternion = to_quaternion(EulerAngles(0.3, 0.2, 0.1))
    assert same_rotation(quaternion, Quaternion(*(-value for value in quaternion)))
    assert not same_rotation(quaternion, to_quaternion(EulerAngles(0.3, 0.2, 0.2)))


@pytest.mark.parametrize("args, angles", [
    ([], EulerAngles(0.0, 0.0, math.pi / 2)),
    (["0.1", "-0.2", "3"], EulerAngles(0.1, -0.2, 3.0)),
])
def test_angle_arguments(args, angles):
    assert parse_angles(args) == angles


@pytest.mark.parametrize("args, reason", [
    (["1"], "expected 0 or 3 arguments (ROLL PITCH YAW); got 1"),
    (["1", "2", "3", "4"], "expected 0 or 3 arguments (ROLL PITCH YAW); got 4"),
    (["1", "north", "3"], "'north' is not a number"),
    (["1", "nan", "3"], "nan is not a finite angle"),
    (["inf", "0", "0"], "inf is not a finite angle"),
])
def test_wrong_angle_arguments(args, reason):
    with pytest.raises(UsageError) as caught:
        parse_angles(args)
    assert str(caught.value) == reason
