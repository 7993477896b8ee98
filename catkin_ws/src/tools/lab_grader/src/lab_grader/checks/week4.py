"""The Week 4 checks: call each service the way the course does and judge the reply and what the robot did.

A suite (suites/week4.yaml, loaded by lab_grader.suite_file) lists the checks as data; this module runs them in
order against a context (lab_grader.checks.context.GradingContext, or any object with the same methods) and
judges each observation (`judge`, plain Python):

- error: the service was not found, the call raised (the server's callback failed, the connection broke), it
  did not reply within the check's `timeout_s` seconds of SIM time ("no reply within N s of sim time"; sim time
  so that the verdict is the same at any real-time factor), or the robot could not be prepared (it would not
  rest after the reset, the simulator stopped). Every exception inside a check ends as an error verdict with its
  text; the runner goes on with the next check.
- fail: it replied and was measured, and some expectation does not hold; the reason lists each one as
  "expected ..., <what happened>" (e.g. "expected to drive forwards 0.4..0.6 m along its initial heading, it drove
  backwards 0.500 m").
- pass: every expectation holds; the reason sums up the reply and the measured motion.

`main()` is `rosrun lab_grader run_checks --suite <name or path> --out <results.json> [--check-timeout S]`:
the results file (lab_grader.checks.verdicts) is always written, atomically, also when checks errored or the
runner was interrupted (then "complete": false); exit code 0 once it is written, 2 for a bad suite or arguments
(nothing written), 1 if the file could not be written.
"""
import argparse
import sys
import time
from pathlib import Path

from lab_grader.checks.motion import MotionError, summarize, thin
from lab_grader.checks.verdicts import (
    CheckResult,
    Interrupted,
    Verdict,
    results_document,
    summarize_verdicts,
    write_results,
)
from lab_grader.suite_file import SuiteError, load_suite

NEGLIGIBLE_M = 0.005
NEGLIGIBLE_DEG = 0.5
MAX_SHOWN_TEXT = 80


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


def shown(value):
    """A reply value for a one-line reason: strings quoted and cut at MAX_SHOWN_TEXT characters."""
    if isinstance(value, str):
        text = value if len(value) <= MAX_SHOWN_TEXT else value[:MAX_SHOWN_TEXT - 3] + "..."
        return repr(text)
    return repr(value)


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

def same_value(got, want):
    """Reply field equality, strict about kinds: True is not 1, 1 equals 1.0 (float32 fields: within 1e-6)."""
    if isinstance(want, bool) or isinstance(got, bool):
        return isinstance(got, bool) and isinstance(want, bool) and got == want
    if isinstance(want, (int, float)):
        return isinstance(got, (int, float)) and abs(got - want) <= 1e-6 * max(1.0, abs(want))
    return got == want


def reply_problems(expect, reply):
    problems = []
    for field, want in expect.reply.items():
        if field not in reply:
            problems.append("expected a reply field {}, the reply has none".format(field))
        elif not same_value(reply[field], want):
            problems.append("expected {} {}, it replied {}".format(field, shown(want), shown(reply[field])))
    for field, pattern in expect.reply_matches.items():
        if field not in reply:
            problems.append("expected a reply field {}, the reply has none".format(field))
        elif not pattern.search(str(reply[field])):
            problems.append("expected {} to match /{}/, it replied {}".format(field, pattern.pattern,
                                                                              shown(reply[field])))
    return problems


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
    evidence["trajectory"] = thin(observation.samples, observation.sent_s)
    if observation.front_measured:
        front = observation.front_distance_m
        evidence["front_distance_m"] = None if front is None else round(front, 4)
    return evidence


def judge(check, observation, settle_s) -> Verdict:
    """The verdict on one observation (motion.Observation) of `check` (suite_file.CheckSpec)."""
    try:
        motion = summarize(observation.samples, observation.sent_s)
    except MotionError:
        motion = None
    evidence = evidence_of(check, observation, motion)
    if observation.error is not None:
        return Verdict.errored(observation.error, evidence)
    if motion is None:
        return Verdict.errored("no /odom was recorded during the call: is the simulator running?", evidence)
    expect = check.expect
    problems = reply_problems(expect, observation.reply)
    if expect.motion is not None:
        problems += motion_problems(expect.motion, motion, settle_s)
    problems += front_problems(expect.front_distance_m, observation)
    if problems:
        return Verdict.failed("; ".join(problems), evidence)
    summary = "replied {}; {}".format(reply_words(observation.reply), motion_words(motion))
    if observation.front_measured and observation.front_distance_m is not None:
        summary += "; front LiDAR {:.3f} m".format(observation.front_distance_m)
    return Verdict.passed(summary, evidence)


# ---- running a suite ------------------------------------------------------------------------------------------------

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
    except Exception as error:  # noqa: BLE001 - a check never crashes the runner
        return Verdict.errored("{}: {}".format(type(error).__name__, error), evidence_of(check, None, None))


def run_suite(suite, make_context, check_timeout_s=None, log=print):
    """Run every check of `suite` with a context from `make_context()`; returns the results document."""
    wall_start = time.monotonic()
    services = {spec.name: {"expected_type": spec.type, "found": None, "found_by": None, "found_type": None,
                            "note": "not looked up"} for spec in suite.services}
    found = {}
    results = []
    context = None
    setup_error = None
    interrupted = False
    sim_start = None
    try:
        context = make_context()
        context.wait_until_ready()
        sim_start = context.now()
        found = context.find_services(suite.services, suite.by_type_grace_s)
        services = {name: service.as_json() for name, service in found.items()}
        for name, service in found.items():
            log("service {}: {}".format(name, "{} ({}, {})".format(service.found, service.found_by,
                                                                   service.found_type)
                                        if service.found else "not found: {}".format(service.note)))
    except (Interrupted, KeyboardInterrupt):
        interrupted = True
        setup_error = "the runner was interrupted before the checks started"
    except Exception as error:  # noqa: BLE001 - the results file is written whatever happens
        setup_error = "{}: {}".format(type(error).__name__, error)
        log("setup failed: " + setup_error)

    for number, check in enumerate(suite.checks, start=1):
        if interrupted:
            verdict = Verdict.errored("not run: the runner was interrupted", evidence_of(check, None, None))
        elif setup_error is not None:
            verdict = Verdict.errored("not run: " + setup_error, evidence_of(check, None, None))
        else:
            if check_timeout_s is not None:
                check = check._replace(timeout_s=check_timeout_s)
            try:
                verdict = run_check(check, suite, context, found.get(check.service))
            except (Interrupted, KeyboardInterrupt):
                interrupted = True
                verdict = Verdict.errored("not run: the runner was interrupted", evidence_of(check, None, None))
        result = CheckResult(check.id, check.title, check.weight, verdict)
        results.append(result)
        log("[{}/{}] {}".format(number, len(suite.checks), summarize_verdicts([result])[0]))

    timing = {"wall_s": round(time.monotonic() - wall_start, 2)}
    if context is not None and sim_start is not None:
        try:
            timing["sim_s"] = round(context.now() - sim_start, 2)
            context.stop_robot()
        except Exception:  # noqa: BLE001 - the graph may be gone; the results matter more
            pass
    return results_document(suite.name, services, results, complete=not interrupted, timing=timing)


# ---- command line ---------------------------------------------------------------------------------------------------

def positive_seconds(text):
    try:
        value = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError("{!r} is not a number of seconds".format(text)) from None
    if not value > 0 or value == float("inf"):
        raise argparse.ArgumentTypeError("must be a positive number of seconds, got {!r}".format(text))
    return value


def parse_args(argv):
    parser = argparse.ArgumentParser(
        prog="run_checks", description="Run a grading suite's checks against the services on this ROS master "
        "(tb3_sim and the student's nodes must be running) and write the results as JSON.")
    parser.add_argument("--suite", required=True, help="a suite name (suites/<name>.yaml) or a suite file path")
    parser.add_argument("--out", required=True, type=Path, help="the results file to write (JSON)")
    parser.add_argument("--check-timeout", type=positive_seconds, default=None, metavar="S",
                        help="reply timeout of every check, seconds of sim time (default: each check's timeout_s)")
    # ROS remappings (name:=value) are for rospy, not for us, as rospy.myargv would strip them.
    return parser.parse_args([arg for arg in argv if ":=" not in arg])


def main(argv=None):
    args = parse_args(sys.argv[1:] if argv is None else argv)
    try:
        suite = load_suite(args.suite)
    except SuiteError as error:
        print("run_checks: {}".format(error), file=sys.stderr)
        return 2

    contexts = []

    def make_context():
        # Imported here so that the checks' logic above imports (and is unit-tested) without rospy.
        from lab_grader.checks.context import GradingContext
        contexts.append(GradingContext())
        return contexts[-1]

    document = run_suite(suite, make_context, args.check_timeout, log=lambda line: print(line, flush=True))
    try:
        write_results(args.out, document)
    except OSError as error:
        print("run_checks: cannot write {}: {}".format(args.out, error), file=sys.stderr)
        return 1
    finally:
        for context in contexts:
            context.shutdown()
    print("score {}/{} -> {}".format(document["score"], document["max_score"], args.out), flush=True)
    return 0
