"""The demo report: measured outcomes in words and numbers, and the table layout."""
import math

import pytest

from week4_services.demo_tour import TOUR, Pose, Stop, describe_outcome, describe_request, format_table


def test_tour_covers_each_service_and_a_refusal_of_each_kind():
    services = {stop.service for stop in TOUR}
    assert services == {"/move_service", "/timed_move_service", "/approach_service"}
    assert Stop("/timed_move_service", ("jump", 2), "travel") in TOUR
    assert any(stop.service == "/approach_service" and stop.args[1] > 0.26 for stop in TOUR)


def test_request_reads_like_the_call():
    assert describe_request(Stop("/timed_move_service", ("left", 3), "turn")) == "/timed_move_service 'left' 3"


def test_reversing_is_negative_travel():
    stop = Stop("/timed_move_service", ("back", 2), "travel")
    assert describe_outcome(stop, Pose(1.0, 0.0, 0.0), Pose(0.8, 0.0, 0.0), math.inf) == "moved -0.200 m"


def test_turn_reports_degrees():
    stop = Stop("/timed_move_service", ("left", 3), "turn")
    assert describe_outcome(stop, Pose(0, 0, 3.0), Pose(0, 0, -3.0), math.inf).startswith("turned +16.2 deg")


@pytest.mark.parametrize("front, text", [(0.4012, "front LiDAR 0.401 m (asked 0.40 m)"),
                                         (math.inf, "front LiDAR nothing ahead (asked 0.40 m)")])
def test_approach_reports_the_front_distance(front, text):
    stop = Stop("/approach_service", (0.4, 0.1), "approach")
    assert describe_outcome(stop, Pose(0, 0, 0), Pose(0.9, 0, 0), front).startswith(text)


def test_table_aligns_columns_under_a_rule():
    table = format_table(("#", "request"), [(1, "/move_service True"), (10, "x")]).splitlines()
    assert table == ["#   request", "--  ------------------", "1   /move_service True", "10  x"]
