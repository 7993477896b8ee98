"""Search goals: the accepted ranges, the refusals naming every bad field, the result fields and the texts."""
import math

import pytest

from tb3_client.scan_ahead import ObjectAhead
from week4_services.approach import Outcome
from week4_services.requests import ApproachPlan
from week5_actions.search_goal import (
    InvalidSearchGoal,
    SearchSummary,
    outcome_text,
    plan_search,
    preempted_text,
    succeeded,
    summary,
)


def test_the_course_goal_becomes_an_approach_plan():
    assert plan_search(0.1, 0.4) == ApproachPlan(distance=0.4, velocity=0.1)


@pytest.mark.parametrize("velocity, distance", [(0.26, 0.2), (1e-3, 3.499), (0.1, 0.2)])
def test_edges_of_the_accepted_ranges(velocity, distance):
    assert plan_search(velocity, distance) == ApproachPlan(distance, velocity)


@pytest.mark.parametrize("velocity, distance, reason", [
    (0.3, 0.4, "fwd_velocity 0.3 m/s is not in (0, 0.26]: the robot drives forwards, at most at the TurtleBot3's "
               "top speed"),
    (0.0, 0.4, "fwd_velocity 0 m/s is not in (0, 0.26]"),
    (-0.1, 0.4, "fwd_velocity -0.1 m/s is not in (0, 0.26]"),
    (math.nan, 0.4, "fwd_velocity nan m/s is not in (0, 0.26]"),
    (0.1, -0.4, "approach_distance -0.4 m is not in [0.2, 3.5): the LiDAR sees from 0.12 m to 3.5 m"),
    (0.1, 0.1, "approach_distance 0.1 m is not in [0.2, 3.5)"),
    (0.1, 3.5, "approach_distance 3.5 m is not in [0.2, 3.5)"),
    (0.1, math.inf, "approach_distance inf m is not in [0.2, 3.5)"),
])
def test_bad_fields_are_refused_with_their_reason(velocity, distance, reason):
    with pytest.raises(InvalidSearchGoal) as refused:
        plan_search(velocity, distance)
    assert str(refused.value).startswith(reason)


def test_every_bad_field_is_named_at_once():
    with pytest.raises(InvalidSearchGoal, match=r"^fwd_velocity 0.5 .*; approach_distance -1 m"):
        plan_search(0.5, -1.0)


def test_the_result_holds_the_travel_and_the_closest_object_ahead():
    assert summary(0.8, ObjectAhead(0.41, -2.5)) == SearchSummary(0.8, 0.41, -2.5)


def test_nothing_ahead_reads_inf_at_0_degrees():
    assert summary(3.5, None) == SearchSummary(3.5, math.inf, 0.0)


@pytest.mark.parametrize("outcome, ok", [(Outcome.ARRIVED, True), (Outcome.ALREADY_THERE, True),
                                         (Outcome.NOTHING_AHEAD, False), (Outcome.TIME_LIMIT, False)])
def test_only_reaching_the_distance_succeeds(outcome, ok):
    assert succeeded(outcome) is ok


def test_texts_say_what_happened():
    plan = plan_search(0.1, 0.4)
    arrived = outcome_text(plan, Outcome.ARRIVED, summary(0.8, ObjectAhead(0.403, 1.0)))
    assert arrived == ("Stopped 0.40 m from the object ahead: travelled 0.800 m, the closest object ahead is "
                       "0.403 m away at +1.0 degrees.")
    assert "safety limit with no object in range ahead: travelled 3.500 m" in outcome_text(
        plan, Outcome.NOTHING_AHEAD, summary(3.5, None))
    assert "60 s time limit" in outcome_text(plan, Outcome.TIME_LIMIT, summary(0.1, None))
    assert "Did not move, already within 0.40 m" in outcome_text(plan, Outcome.ALREADY_THERE,
                                                                  summary(0.0, ObjectAhead(0.3, 0.0)))
    assert preempted_text(summary(0.25, None)) == "Cancelled: stopped after 0.250 m."
