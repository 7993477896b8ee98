"""movement_client's arguments: one move calls /movement, a direction, velocity and time call /move."""
import pytest

from movement_pkg.client_request import USAGE, ClientRequest, client_request
from movement_pkg.moves import InvalidRequest


def test_one_move_is_a_movement_request():
    assert client_request(["Stop"]) == ClientRequest("/movement", ("Stop",))
    assert client_request(["Turn Right"]) == ClientRequest("/movement", ("Turn Right",))


def test_three_arguments_are_a_move_request():
    assert client_request(["left", "0.2", "5"]) == ClientRequest("/move", ("left", 0.2, 5))


@pytest.mark.parametrize("arguments, text", [
    ([], "expected one move or a direction, a velocity and a time; got 0 arguments"),
    (["left", "0.2"], "got 2 arguments"),
    (["left", "fast", "5"], "velocity 'fast' is not a number"),
    (["left", "0.2", "5.5"], "time '5.5' is not a whole number of seconds"),
])
def test_other_arguments_are_refused_with_the_reason(arguments, text):
    with pytest.raises(InvalidRequest, match=text):
        client_request(arguments)


def test_the_usage_shows_both_forms():
    assert 'movement_client "<move>"' in USAGE and "movement_client <direction> <velocity> <time>" in USAGE
