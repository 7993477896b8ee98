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
- pass: every expectation holds; the reason sums up the state, the result and the feedback;
- interference: the submission tampered with the measurement while the goal ran (as for a service check).

With a world, the robot is reset and at rest before the goal is sent, and its true motion is recorded from then
until `settle_s` after the goal ended (lab_grader.checks.motion): the motion and front distance are judged as a
service check's. Each kind of expectation is one function in EXPECTATION_JUDGES, `(expect, observation, motion,
settle_s) -> [problem, ...]`; a new kind is one function and one line there.
"""
from typing import Any, Dict, List, NamedTuple, Optional, Tuple

from lab_grader.checks.fields import field_problems, same_value, shown
from lab_grader.checks.image_folder import ImageFolder
from lab_grader.checks.motion import MotionError, Sample, summarize, thin
from lab_grader.checks.service_checks import front_problems, motion_problems, motion_words
from lab_grader.checks.verdicts import InterferenceError, Interrupted, Verdict

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
    samples: Optional[Tuple[Sample, ...]] = None   # ground truth from before the goal to settle_s after its end
    front_distance_m: Optional[float] = None
    front_measured: bool = False
    interference: Tuple[str, ...] = ()
    images: Optional[ImageFolder] = None             # the saved images the result names (expect.images)


def feedback_values(observation, field) -> List[Any]:
    return [fields.get(field) for _, fields in observation.feedback]


def state_words(observation):
    text = observation.status_text
    return "{}{}".format(observation.state, " ({})".format(shown(text)) if text else "")


def motion_of(observation):
    """The MotionSummary of the observation's samples from the moment the goal was sent, or None."""
    if not observation or not observation.samples:
        return None
    try:
        return summarize(observation.samples, observation.sent_s)
    except MotionError:
        return None


def evidence_of(check, observation):
    evidence = {"goal": dict(check.goal), "cancel_after_s": check.cancel_after_s, "timeout_s": check.timeout_s,
                "state": None, "result": None, "feedback": []}
    if observation is None:
        return evidence
    motion = motion_of(observation)
    if motion is not None:
        evidence.update(motion=motion.as_evidence(), trajectory=thin(observation.samples, observation.sent_s))
    if observation.front_measured:
        front = observation.front_distance_m
        evidence["front_distance_m"] = None if front is None else round(front, 4)
    if observation.images is not None:
        evidence["images"] = {"folder": observation.images.named, "files": list(observation.images.images),
                              "decodable": len(observation.images.decodable), "problem": observation.images.problem}
    evidence.update(state=observation.state, status_text=observation.status_text, result=observation.result,
                    feedback=[[round(t, 3), fields] for t, fields in observation.feedback[:MAX_FEEDBACK_EVIDENCE]])
    if observation.ended_s is not None:
        evidence["ended_after_s"] = round(observation.ended_s - observation.sent_s, 3)
    if observation.cancelled_s is not None:
        evidence["cancelled_after_s"] = round(observation.cancelled_s - observation.sent_s, 3)
    return evidence


def state_problems(expect, observation, motion, settle_s):
    if expect.states and observation.state not in expect.states:
        return ["expected the goal to end {}, it ended {}".format(" or ".join(expect.states),
                                                                state_words(observation))]
    return []


def result_problems(expect, observation, motion, settle_s):
    result = observation.result or {}
    problems = field_problems(expect.result, expect.result_matches, result, what="result")
    for field, wanted in expect.result_ranges.items():
        value = result.get(field)
        if not isinstance(value, (int, float)) or isinstance(value, bool) or not wanted.contains(value):
            problems.append("expected result {} {}, it was {}".format(field, wanted.describe(),
                                                                      "missing" if field not in result
                                                                      else shown(value)))
    return problems


def timing_problems(expect, observation, motion, settle_s):
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


def feedback_problems(expect, observation, motion, settle_s):
    problems = []
    for field, wanted in expect.feedback.items():
        got = feedback_values(observation, field)
        if len(got) != len(wanted) or not all(same_value(g, w) for g, w in zip(got, wanted)):
            problems.append("expected feedback {} {}, it sent {}".format(field, list(wanted), got))
    count = len(observation.feedback)
    if expect.feedback_count is not None and not expect.feedback_count.contains(count):
        problems.append("expected {} feedback messages, it sent {}".format(expect.feedback_count.describe(), count))
    for field in expect.feedback_rising:
        got = feedback_values(observation, field)
        if not all(isinstance(value, (int, float)) for value in got):
            problems.append("expected feedback {} never to decrease, it sent {}".format(field, got))
            continue
        falls = [(a, b) for a, b in zip(got, got[1:]) if b < a]
        if falls:
            problems.append("expected feedback {} never to decrease, it went {} -> {}".format(
                field, shown(falls[0][0]), shown(falls[0][1])))
    return problems


def robot_problems(expect, observation, motion, settle_s):
    if expect.motion is None and expect.front_distance_m is None:
        return []
    if motion is None:
        return ["expected to measure the robot, no ground truth was recorded during the goal"]
    problems = motion_problems(expect.motion, motion, settle_s) if expect.motion is not None else []
    return problems + front_problems(expect.front_distance_m, observation)


def images_problems(expect, observation, motion, settle_s):
    wanted = expect.images
    if wanted is None:
        return []
    found = observation.images
    expected = "expected {} decodable image{} in the folder result {} names".format(
        wanted.count, "" if wanted.count == 1 else "s", wanted.path_field)
    if found is None:
        return [expected + ", the images were not looked at"]
    if found.problem is not None:
        return ["{} ({}): {}".format(expected, shown(found.named), found.problem)]
    if len(found.images) != wanted.count or len(found.decodable) != wanted.count:
        return ["{} ({}), it holds {} image file{}, {} of them decodable".format(
            expected, shown(found.named), len(found.images), "" if len(found.images) == 1 else "s",
            len(found.decodable))]
    return []


EXPECTATION_JUDGES = (state_problems, result_problems, feedback_problems, timing_problems, robot_problems,
                      images_problems)


def judge_action(check, observation, settle_s=0.0) -> Verdict:
    """The verdict on one ActionObservation of an action `check` (suite_file.CheckSpec with `action`)."""
    evidence = evidence_of(check, observation)
    if observation.interference:
        return Verdict.interfered(observation.interference, evidence)
    if observation.error is not None:
        return Verdict.errored(observation.error, evidence)
    motion = motion_of(observation)
    problems = [problem for judge_kind in EXPECTATION_JUDGES
                for problem in judge_kind(check.expect, observation, motion, settle_s)]
    if problems:
        return Verdict.failed("; ".join(problems), evidence)
    result = ", ".join("{}={}".format(field, shown(value)) for field, value in (observation.result or {}).items())
    summary = "ended {} after {:.2f} s with {}; {} feedback messages".format(
        state_words(observation), observation.ended_s - observation.sent_s, result or "an empty result",
        len(observation.feedback))
    if motion is not None:
        summary += "; " + motion_words(motion)
    if observation.front_measured and observation.front_distance_m is not None:
        summary += "; front LiDAR {:.3f} m".format(observation.front_distance_m)
    return Verdict.passed(summary, evidence)


def run_action_check(check, suite, context, found) -> Verdict:
    """Prepare the robot (with a world), send the goal, observe, judge; every exception becomes an error verdict
    (Interrupted is passed on)."""
    if found is None or found.found is None:
        note = found.note if found is not None else "the actions were not looked up"
        return Verdict.errored("action {} not found: {}".format(check.action, note), evidence_of(check, None))
    try:
        context.prepare(suite.still_timeout_s)
        observation = context.observe_action(
            found, check.goal, check.timeout_s, check.cancel_after_s, settle_s=suite.settle_s,
            measure_front=check.expect.front_distance_m is not None)
        if observation.error is not None:
            context.stop_robot()    # a goal that never ended may have left the robot driving
        elif check.expect.images is not None:
            observation = observation._replace(images=context.inspect_images(
                (observation.result or {}).get(check.expect.images.path_field)))
        return judge_action(check, observation, suite.settle_s)
    except Interrupted:
        raise
    except InterferenceError as error:
        return Verdict.interfered(error.findings, evidence_of(check, None))
    except Exception as error:  # noqa: BLE001 - a check never crashes the runner
        return Verdict.errored("{}: {}".format(type(error).__name__, error), evidence_of(check, None))
