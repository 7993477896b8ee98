"""A Search goal (tuos_msgs/Search) as a plan, and the texts and numbers of its result (plain Python, no rospy).

The COM2009 Part 5 search server drives straight ahead at `fwd_velocity` (m/s) until the closest object ahead is
`approach_distance` (m) away, publishing the distance travelled as feedback, and ends with the total distance
travelled and the closest object's distance (m) and angle (degrees) in the result. The driving itself is the
Week 4 approach controller (week4_services.approach: dead-reckoned between LiDAR sweeps, braking distance, the
3.5 m and 60 s safety limits); this module adds what the action adds.

Choices where the course is silent, kept consistent with the Week 4 approach service:
- fwd_velocity is in (0, 0.26] m/s (the Waffle's top speed); approach_distance in [0.2, 3.5) m (the LiDAR sees
  nothing closer than 0.12 m and the body needs room; 3.5 m is its range). NaN and infinities are refused; every
  bad field is named, with what is allowed, in one reason.
- "Ahead" is the LiDAR arc of +-20 degrees around straight ahead (tb3_client.scan_ahead); closest_object_angle is
  degrees anticlockwise from straight ahead (negative: to the right). With nothing in range ahead the closest
  object distance is inf (as LaserScan writes "nothing seen") and its angle 0.
- Feedback goes out once per LiDAR sweep (5 Hz of sim time) while driving, and once more at the end, so a client
  always sees the final distance.
- Outcomes: stopped at the distance, or already within it: SUCCEEDED; nothing within range after 3.5 m, or still
  driving after 60 s: ABORTED with the reason (the result fields still filled in); cancelled: PREEMPTED, the robot
  stopped at once.
"""
import math
from typing import NamedTuple, Optional

from tb3_client.motion import MAX_LINEAR_MPS
from tb3_client.scan_ahead import ObjectAhead
from week4_services.approach import SAFETY_TRAVEL_M, TIME_LIMIT_S, Outcome
from week4_services.requests import MAX_APPROACH_DISTANCE_M, MIN_APPROACH_DISTANCE_M, ApproachPlan

NOTHING_AHEAD_M = math.inf
SUCCEEDED_OUTCOMES = (Outcome.ARRIVED, Outcome.ALREADY_THERE)


class InvalidSearchGoal(ValueError):
    """The goal is refused before the robot moves; the text names each bad field and what is allowed."""


class SearchSummary(NamedTuple):
    """The result's three fields: metres travelled, and the closest object ahead (m, degrees CCW)."""

    total_distance_travelled: float
    closest_object_distance: float
    closest_object_angle: float


def plan_search(fwd_velocity, approach_distance):
    """The ApproachPlan (distance, velocity) for a goal, or InvalidSearchGoal listing every bad field."""
    problems = []
    if not math.isfinite(fwd_velocity) or not 0.0 < fwd_velocity <= MAX_LINEAR_MPS:
        problems.append("fwd_velocity {:g} m/s is not in (0, {:g}]: the robot drives forwards, at most at the "
                        "TurtleBot3's top speed".format(fwd_velocity, MAX_LINEAR_MPS))
    if not math.isfinite(approach_distance) or not (
            MIN_APPROACH_DISTANCE_M <= approach_distance < MAX_APPROACH_DISTANCE_M):
        problems.append("approach_distance {:g} m is not in [{:g}, {:g}): the LiDAR sees from 0.12 m to 3.5 m".format(
            approach_distance, MIN_APPROACH_DISTANCE_M, MAX_APPROACH_DISTANCE_M))
    if problems:
        raise InvalidSearchGoal("; ".join(problems))
    return ApproachPlan(float(approach_distance), float(fwd_velocity))


def summary(travelled_m, ahead: Optional[ObjectAhead]):
    """The result fields from the distance travelled and the closest object ahead (None: nothing in range)."""
    if ahead is None:
        return SearchSummary(float(travelled_m), NOTHING_AHEAD_M, 0.0)
    return SearchSummary(float(travelled_m), float(ahead.distance), float(ahead.angle_deg))


def succeeded(outcome):
    """Whether an approach that ended with `outcome` (week4_services.approach.Outcome) is a successful search."""
    return outcome in SUCCEEDED_OUTCOMES


def outcome_text(plan, outcome, result: SearchSummary):
    """The goal's status text: what happened, the travel and the closest object ahead."""
    seen = ("nothing in range ahead" if math.isinf(result.closest_object_distance)
            else "the closest object ahead is {:.3f} m away at {:+.1f} degrees".format(
                result.closest_object_distance, result.closest_object_angle))
    travelled = "travelled {:.3f} m".format(result.total_distance_travelled)
    if outcome is Outcome.ARRIVED:
        return "Stopped {:.2f} m from the object ahead: {}, {}.".format(plan.distance, travelled, seen)
    if outcome is Outcome.ALREADY_THERE:
        return "Did not move, already within {:.2f} m: {}.".format(plan.distance, seen)
    if outcome is Outcome.TIME_LIMIT:
        return "Stopped after the {:.0f} s time limit: {}, {}.".format(TIME_LIMIT_S, travelled, seen)
    return "Stopped after the {:g} m safety limit with no object in range ahead: {}.".format(
        SAFETY_TRAVEL_M, travelled)


def preempted_text(result: SearchSummary):
    return "Cancelled: stopped after {:.3f} m.".format(result.total_distance_travelled)
