"""Service checks: call a service the way the course does and judge the reply and what the robot did.

A suite (suites/week4.yaml, loaded by lab_grader.suite_file) lists the checks as data; `run_check` makes one
against a context (lab_grader.checks.context.GradingContext, or any object with the same methods) and `judge`
(plain Python) gives the verdict on what it observed:

- error: the service was not found, the call raised (the server's callback failed, the connection broke), it
  did not reply within the check's `timeout_s` seconds of SIM time ("no reply within N s of sim time"; sim time
  so that the verdict is the same at any real-time factor), or the robot could not be prepared (it would not
  rest after the reset, the simulator stopped). Every exception inside a check ends as an error verdict with its
  text; the runner goes on with the next check.
- fail: it replied and was measured, and some expectation does not hold; the reason lists each one as
  "expected ..., <what happened>" (e.g. "expected to drive forwards 0.4..0.6 m along its initial heading, it drove
  backwards 0.500 m").
- pass: every expectation holds; the reason sums up the reply and the measured motion.
- interference: the submission tampered with the measurement during the check (lab_grader.checks.interference:
  paused physics, a teleport, a forged /odom or /clock); whatever the robot did, the reason names the tampering.
- `refused: true` turns it around for a call that must fail (an int64 sum out of range): the server raising
  passes, with its text as the reason, and a reply fails.

A suite without a world has no robot: its observations carry no /odom samples (None) and only the reply is judged.
"""
from lab_grader.checks.fields import field_problems, shown
from lab_grader.checks.motion import MotionError, summarize, thin
from lab_grader.checks.verdicts import InterferenceError, Interrupted, Verdict

NEGLIGIBLE_M = 0.005
NEGLIGIBLE_DEG = 0.5


# ---- words for numbers ----------------------------------------------------------------------------------------------

def signed(value, decimals):
    """`value` with a sign, never "-0.000": what rounds to zero reads +0.000."""
    rounded = round(value, decimals) + 0.0
    return "{:+.{}f}".format(0.0 if rounded == 0 else rounded, decimals)


def travel_words(forward_m):
    if abs(forward_m) < NEGLIGIBLE_M:
        return "did not drive along its heading ({} m)".format(signed(forward_m, 3))
    return "drove {} {:.3f} m".format("forwards" if forward_m > 0 else "backwards", abs(forward_m))


def turn_words(turn_deg):
    if abs(turn_deg) < NEGLIGIBLE_DEG:
        return "did not turn ({} deg)".format(signed(turn_deg, 1))
    return "turned {} {:.1f} deg".format("counter-clockwise" if turn_deg > 0 else "clockwise", abs(turn_deg))


def _expected_signed(wanted, unit, positive, negative, either):
    """A signed range in words: `positive` or `negative` with the range made positive, or `either` with it."""
    if wanted.min is not None and wanted.min > 0:
        return positive + " " + wanted.describe(unit)
    if wanted.max is not None and wanted.max < 0:
        flipped = type(wanted)(-wanted.max, None if wanted.min is None else -wanted.min)
        return negative + " " + flipped.describe(unit)
    return either + " " + wanted.describe(unit)


def expected_travel(wanted):
    """'forwards 0.4..0.6 m', 'backwards at least 0.05 m', or a plain signed range."""
    return _expected_signed(wanted, "m", "forwards", "backwards", "a signed distance of")


def expected_turn(wanted):
    return _expected_signed(wanted, "deg", "counter-clockwise", "clockwise", "a signed heading change of")


def reply_words(reply):
    return ", ".join("{}={}".format(field, shown(value)) for field, value in reply.items()) or "an empty reply"


def motion_words(motion):
    if not motion.moved and motion.excursion_m < NEGLIGIBLE_M:
        return "did not move ({:.3f} m, {} deg)".format(motion.excursion_m, signed(motion.turn_deg, 1))
    ending = "still at the end" if motion.still_at_end else "still moving at the end"
    return "{}, {}, lateral {} m, motion {:.2f} s, {}".format(
        travel_words(motion.forward_m), turn_words(motion.turn_deg), signed(motion.lateral_m, 3), motion.duration_s,
        ending)


# ---- judging one observation ----------------------------------------------------------------------------------------

def motion_problems(wanted, motion, settle_s):
    problems = []
    if wanted.forward_m is not None and not wanted.forward_m.contains(motion.forward_m):
        problems.append("expected to drive {} along its initial heading, it {}".format(
            expected_travel(wanted.forward_m), travel_words(motion.forward_m)))
    if wanted.lateral_max_m is not None and abs(motion.lateral_m) > wanted.lateral_max_m:
        problems.append("expected at most {:g} m sideways, it drifted {:.3f} m to the {}".format(
            wanted.lateral_max_m, abs(motion.lateral_m), "left" if motion.lateral_m > 0 else "right"))
    if wanted.turn_deg is not None and not wanted.turn_deg.contains(motion.turn_deg):
        problems.append("expected to turn {}, it {}".format(expected_turn(wanted.turn_deg),
                                                            turn_words(motion.turn_deg)))
    if wanted.turn_max_deg is not None and abs(motion.turn_deg) > wanted.turn_max_deg:
        problems.append("expected a heading change of at most {:g} deg, it {}".format(
            wanted.turn_max_deg, turn_words(motion.turn_deg)))
    if wanted.duration_s is not None and not (motion.stop_s is not None
                                              and wanted.duration_s.contains(motion.duration_s)):
        if not motion.moved:
            happened = "it did not move"
        elif motion.stop_s is None:
            happened = "it was still moving {:.2f} s after it started".format(motion.duration_s)
        else:
            happened = "it moved for {:.2f} s".format(motion.duration_s)
        problems.append("expected the motion to last {} of sim time, {}".format(wanted.duration_s.describe("s"),
                                                                               happened))
    if wanted.mean_speed_mps is not None and not wanted.mean_speed_mps.contains(motion.mean_speed_mps):
        problems.append("expected to drive at a mean forward speed of {}, it drove at {} m/s".format(
            wanted.mean_speed_mps.describe("m/s"), signed(motion.mean_speed_mps, 3)))
    if wanted.excursion_max_m is not None and motion.excursion_m > wanted.excursion_max_m:
        problems.append("expected to stay within {:g} m of where it started, it got {:.3f} m away".format(
            wanted.excursion_max_m, motion.excursion_m))
    if wanted.still_at_end is not None and motion.still_at_end != wanted.still_at_end:
        problems.append("expected the robot {} {:g} s after the reply, it was {} (v={} m/s, w={} rad/s)".format(
            "to be still" if wanted.still_at_end else "to be moving", settle_s,
            "still" if motion.still_at_end else "moving", signed(motion.end_v, 3), signed(motion.end_w, 3)))
    return problems


def front_problems(wanted, observation):
    if wanted is None:
        return []
    if not observation.front_measured:
        return ["expected the front LiDAR to read {} once still, it was not measured".format(wanted.describe("m"))]
    distance = observation.front_distance_m
    if distance is None:
        return ["expected the front LiDAR to read {} once still, it saw nothing within +-20 deg".format(
            wanted.describe("m"))]
    if not wanted.contains(distance):
        return ["expected the front LiDAR to read {} once still, it read {:.3f} m".format(wanted.describe("m"),
                                                                                         distance)]
    return []


def evidence_of(check, observation, motion):
    evidence = {"request": dict(check.request), "timeout_s": check.timeout_s, "reply": None, "motion": None,
                "trajectory": []}
    if observation is None:
        return evidence
    evidence["reply"] = observation.reply
    if observation.replied_s is not None:
        evidence["reply_after_s"] = round(observation.replied_s - observation.sent_s, 3)
    if motion is not None:
        evidence["motion"] = motion.as_evidence()
    if observation.samples is not None:
        evidence["trajectory"] = thin(observation.samples, observation.sent_s)
    if observation.server_error:
        evidence["server_error"] = observation.error
    if observation.front_measured:
        front = observation.front_distance_m
        evidence["front_distance_m"] = None if front is None else round(front, 4)
    return evidence


def judge(check, observation, settle_s) -> Verdict:
    """The verdict on one observation (motion.Observation) of `check` (suite_file.CheckSpec)."""
    robot = observation.samples is not None
    motion = None
    if robot:
        try:
            motion = summarize(observation.samples, observation.sent_s)
        except MotionError:
            motion = None
    evidence = evidence_of(check, observation, motion)
    if observation.interference:
        return Verdict.interfered(observation.interference, evidence)
    expect = check.expect
    if observation.error is not None and not (expect.refused and observation.server_error):
        return Verdict.errored(observation.error, evidence)
    if robot and motion is None:
        return Verdict.errored("no /odom was recorded during the call: is the simulator running?", evidence)
    if observation.error is not None:
        problems, summary = [], "refused: {}".format(observation.error)
    else:
        problems = ["expected the call to be refused (the server raising an error), it replied {}".format(
            reply_words(observation.reply))] if expect.refused else []
        problems += field_problems(expect.reply, expect.reply_matches, observation.reply)
        summary = "replied {}".format(reply_words(observation.reply))
    if expect.motion is not None:
        problems += motion_problems(expect.motion, motion, settle_s)
    problems += front_problems(expect.front_distance_m, observation)
    if problems:
        return Verdict.failed("; ".join(problems), evidence)
    if motion is not None:
        summary += "; " + motion_words(motion)
    if observation.front_measured and observation.front_distance_m is not None:
        summary += "; front LiDAR {:.3f} m".format(observation.front_distance_m)
    return Verdict.passed(summary, evidence)


def run_check(check, suite, context, found) -> Verdict:
    """Prepare, call, judge; every exception becomes an error verdict (Interrupted is passed on)."""
    if found is None or found.found is None:
        note = found.note if found is not None else "the services were not looked up"
        return Verdict.errored("service {} not found: {}".format(check.service, note),
                               evidence_of(check, None, None))
    try:
        context.prepare(suite.still_timeout_s)
        observation = context.observe(found, check.request, check.timeout_s, suite.settle_s,
                                      measure_front=check.expect.front_distance_m is not None)
        if observation.error is not None:
            context.stop_robot()    # a hung or failed call may have left the robot driving
        return judge(check, observation, suite.settle_s)
    except Interrupted:
        raise
    except InterferenceError as error:
        return Verdict.interfered(error.findings, evidence_of(check, None, None))
    except Exception as error:  # noqa: BLE001 - a check never crashes the runner
        return Verdict.errored("{}: {}".format(type(error).__name__, error), evidence_of(check, None, None))
