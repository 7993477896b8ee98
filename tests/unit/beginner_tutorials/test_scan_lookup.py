"""The gazebo_server lookup: the /scan range at an index, and clear errors instead of IndexError."""
import pytest

from beginner_tutorials.errors import ScanLookupError, UsageError
from beginner_tutorials.scan_lookup import parse_direction, range_at, usage

FULL_SCAN = tuple(0.5 + index / 100.0 for index in range(360))


@pytest.mark.parametrize("direction", [0, 1, 90, 180, 359])
def test_the_range_at_the_direction_is_returned(direction):
    assert range_at(FULL_SCAN, direction) == pytest.approx(0.5 + direction / 100.0)


def test_inf_is_passed_on_as_nothing_in_range():
    assert range_at((float("inf"), 1.0), 0) == float("inf")


@pytest.mark.parametrize("direction", [360, 400, -1, -360, 2 ** 63 - 1])
def test_direction_outside_the_scan_names_the_allowed_range(direction):
    with pytest.raises(ScanLookupError) as caught:
        range_at(FULL_SCAN, direction)
    assert str(caught.value) == ("direction must be an index from 0 to 359 (the latest /scan has 360 ranges, one "
                                 "per degree counter-clockwise from ahead); got {}".format(direction))


def test_a_shorter_scan_allows_only_its_own_indices():
    with pytest.raises(ScanLookupError, match=r"from 0 to 179 \(the latest /scan has 180 ranges"):
        range_at(FULL_SCAN[:180], 200)


def test_no_scan_yet_is_a_clear_error():
    with pytest.raises(ScanLookupError) as caught:
        range_at(None, 0)
    assert str(caught.value) == "no /scan message received yet: is the robot (or the simulator) running?"


def test_an_empty_scan_is_a_clear_error():
    with pytest.raises(ScanLookupError, match="the latest /scan message has no ranges"):
        range_at((), 0)


@pytest.mark.parametrize("args, direction", [([], 0), (["0"], 0), (["90"], 90), (["359"], 359)])
def test_client_direction_argument(args, direction):
    assert parse_direction(args) == direction


@pytest.mark.parametrize("args, reason", [
    (["360"], "direction 360 is outside 0..359"),
    (["-1"], "direction -1 is outside 0..359"),
    (["ahead"], "'ahead' is not an integer"),
    (["1", "2"], "expected at most 1 argument, DIRECTION; got 2"),
])
def test_client_rejects_wrong_directions(args, reason):
    with pytest.raises(UsageError) as caught:
        parse_direction(args)
    assert str(caught.value) == reason


def test_client_usage_names_the_range():
    assert usage("scan_client.py").startswith("usage: scan_client.py [DIRECTION]\n")
    assert "integer from 0 to 359" in usage("scan_client.py")
