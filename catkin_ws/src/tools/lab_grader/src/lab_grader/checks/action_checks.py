"""Action checks: send a goal to an actionlib server the way the course's client does, maybe cancel it, and judge
how it ended (plain Python; the context does the ROS part).

An `ActionObservation` holds what happened to one goal: its terminal state (actionlib's GoalStatus name), the
status text, the result fields, every feedback message (with its time after the goal was sent), and when the goal
was sent, cancelled and ended (ROS time: sim time under /use_sim_time, else wall time). `judge_action` compares it
with the check's ActionExpectation (suite_file):

- error: the action server was not found, the goal could not be sent, or it did not end within the check's
  timeout_s ("no result within N s");
- fail: it ended, and some expectation does not hold ("expected the goal to end SUCCEEDED, it ended PREEMPTED
  ('Counting preempted after 2 of 10 counts')", "expected feedback counts_elapsed [0, 1, 2], it sent [0, 1]");
- pass: every expectation holds; the reason sums up the state, the result and the feedback.
"""
from typing import Any, Dict, List, NamedTuple, Optional, Tuple

from lab_grader.checks.fields import field_problems, same_value, shown
from lab_grader.checks.verdicts import Interrupted, Verdict

MAX_FEEDBACK_EVIDENCE = 200


class ActionObservation(NamedTuple):
    goal: Dict[str, Any]
    state: Optional[str]                          # terminal GoalStatus name; None when it did not end
    status_text: str
    result: Optional[Dict[str, Any]]
    feedback: Tuple[Tuple[float, Dict[str, Any]], ...]   # (s after the goal was sent, fields)
    sent_s: float
    cancelled_s: Optional[float]
    ended_s: Optional[float]
    error: Optional[str] = None


def feedback_values(observation, field) -> List[Any]:
    return [fields.get(field) for _, fields in observation.feedback]


def state_words(observation):
    text = observation.status_text
    return "{}{}".format(observation.state, " ({})".format(shown(text)) if text else "")


def evidence_of(check, observation):
    evidence = {"goal": dict(check.goal), "cancel_after_s": check.cancel_after_s, "timeout_s": check.timeout_s,
                "state": None, "result": None, "feedback": []}
    if observation is None:
        return evidence
    evidence.update(state=observation.state, status_text=observation.status_text, result=observation.result,
                    feedback=[[round(t, 3), fields] for t, fields in observation.feedback[:MAX_FEEDBACK_EVIDENCE]])
    if observation.ended_s is not None:
        evidence["ended_after_s"] = round(observation.ended_s - observation.sent_s, 3)
    if observation.cancelled_s is not None:
        evidence["cancelled_after_s"] = round(observation.cancelled_s - observation.sent_s, 3)
    return evidence


def timing_problems(expect, observation):
    problems = []
    duration = observation.ended_s - observation.sent_s
    if expect.duration_s is not None and not expect.duration_s.contains(duration):
        problems.append("expected the goal to end {} after it was sent, it ended after {:.2f} s".format(
            expect.duration_s.describe("s"), duration))
    if expect.cancel_to_end_s is not None:
        if observation.cancelled_s is None:
            problems.append("expected to cancel the goal, it ended before the cancel was sent")
        elif not expect.cancel_to_end_s.contains(observation.ended_s - observation.cancelled_s):
            problems.append("expected the goal to end {} after the cancel, it ended after {:.2f} s".format(
                expect.cancel_to_end_s.describe("s"), observation.ended_s - observation.cancelled_s))
    return problems


def feedback_problems(expect, observation):
    problems = []
    for field, wanted in expect.feedback.items():
        got = feedback_values(observation, field)
        if len(got) != len(wanted) or not all(same_value(g, w) for g, w in zip(got, wanted)):
            problems.append("expected feedback {} {}, it sent {}".format(field, list(wanted), got))
    return problems


def judge_action(check, observation) -> Verdict:
    """The verdict on one ActionObservation of an action `check` (suite_file.CheckSpec with `action`)."""
    evidence = evidence_of(check, observation)
    if observation.error is not None:
        return Verdict.errored(observation.error, evidence)
    expect = check.expect
    problems = []
    if expect.states and observation.state not in expect.states:
        problems.append("expected the goal to end {}, it ended {}".format(" or ".join(expect.states),
                                                                        state_words(observation)))
    problems += field_problems(expect.result, expect.result_matches, observation.result or {}, what="result")
    problems += feedback_problems(expect, observation)
    problems += timing_problems(expect, observation)
    if problems:
        return Verdict.failed("; ".join(problems), evidence)
    result = ", ".join("{}={}".format(field, shown(value)) for field, value in (observation.result or {}).items())
    summary = "ended {} after {:.2f} s with {}; {} feedback messages".format(
        state_words(observation), observation.ended_s - observation.sent_s, result or "an empty result",
        len(observation.feedback))
    return Verdict.passed(summary, evidence)


def run_action_check(check, context, found) -> Verdict:
    """Send the goal, observe, judge; every exception becomes an error verdict (Interrupted is passed on)."""
    if found is None or found.found is None:
        note = found.note if found is not None else "the actions were not looked up"
        return Verdict.errored("action {} not found: {}".format(check.action, note), evidence_of(check, None))
    try:
        return judge_action(check, context.observe_action(found, check.goal, check.timeout_s, check.cancel_after_s))
    except Interrupted:
        raise
    except Exception as error:  # noqa: BLE001 - a check never crashes the runner
        return Verdict.errored("{}: {}".format(type(error).__name__, error), evidence_of(check, None))
