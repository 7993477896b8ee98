"""The ROS 2 Services unit ports: request words and numbers become motion plans or named refusals."""
import math

import pytest

from movement_pkg.moves import move_motion, movement_velocity
from services_quiz.turn import turn_motion
from tb3_client.motion import InvalidRequest, Motion


@pytest.mark.parametrize("move, velocity", [("Turn Right", (0.1, -0.5)), ("Turn Left", (0.1, 0.5)),
                                            ("Stop", (0.0, 0.0))])
def test_movement_words(move, velocity):
    assert movement_velocity(move) == velocity


@pytest.mark.parametrize("move", ["turn right", "Turn Up", "", "Stop "])
def test_other_movement_words_are_refused(move):
    with pytest.raises(InvalidRequest, match="is not one of Turn Right, Turn Left, Stop"):
        movement_velocity(move)


@pytest.mark.parametrize("direction, expected", [
    ("forward", Motion(0.2, 0.0, 3.0)), ("backward", Motion(-0.2, 0.0, 3.0)),
    ("left", Motion(0.0, 0.2, 3.0)), ("right", Motion(0.0, -0.2, 3.0)), ("stop", Motion(0.0, 0.0, 0.0)),
])
def test_move_directions(direction, expected):
    assert move_motion(direction, 0.2, 3) == expected


@pytest.mark.parametrize("direction, velocity, time, reason", [
    ("up", 0.1, 2, "direction 'up' is not one of forward, backward, left, right, stop"),
    ("forward", 0.1, 0, "time 0 s must be positive"), ("left", 0.5, -3, "must be positive"),
    ("forward", 0.5, 2, r"velocity 0.5 must be in \(0, 0.26\]"), ("right", 2.0, 2, r"\(0, 1.82\]"),
    ("backward", math.nan, 2, "velocity nan"), ("forward", 0.1, 100, "longer than the 60 s limit"),
])
def test_bad_moves(direction, velocity, time, reason):
    with pytest.raises(InvalidRequest, match=reason):
        move_motion(direction, velocity, time)


def test_quiz_turn_right():
    assert turn_motion("right", 0.2, 10) == Motion(0.0, -0.2, 10.0)


@pytest.mark.parametrize("direction, rate, time", [("Right", 0.2, 10), ("right", -0.2, 10), ("left", 0.2, 0),
                                                   ("left", math.inf, 1)])
def test_quiz_bad_turns(direction, rate, time):
    with pytest.raises(InvalidRequest):
        turn_motion(direction, rate, time)

