"""Running a suite: find the services and actions, run every check in order, score, and write the results file.

`run_suite(suite, make_context)` works against any context with GradingContext's methods (lab_grader.checks.context
is the real one; the unit tests use a fake): service checks go to lab_grader.checks.service_checks, action checks
to lab_grader.checks.action_checks. A check that cannot be run (a service not found, the runner interrupted, the
context failing to start) gets an error verdict; every check of the suite is listed in the results.

`main()` is `rosrun lab_grader run_checks --suite <name or path> --out <results.json> [--check-timeout S]
[--ground-truth SOCKET] [--exercise FILE] [--student-home DIR]` (a suite with a world needs SOCKET, tb3_sim's
~ground_truth_socket; DIR is the HOME of the student's nodes, where image checks look for their files;
--exercise runs only the checks of the services and actions the course's FILE serves):
the results file (lab_grader.checks.verdicts) is always written, atomically, also when checks errored or the
runner was interrupted (then "complete": false); exit code 0 once it is written, 2 for a bad suite or arguments
(nothing written), 1 if the file could not be written. Each check prints one line, `[3/17] pass  timed_fwd ...`,
as it ends (the grader shows the latest in its progress line), and under it where its wall time went (the context's
timeline: `      6.2 s: heard 0.00, reset 0.01, rest 0.20, reply 5.02, tail 1.01, judge 0.01`).

`--serve` (instead of --out) is the grader's way, which runs each exercise's node alone: one runner (one rospy node,
one ground-truth connection, made while the first exercise's node starts) grades exercise after exercise, each on
a line of its stdin, `{"exercise": FILE, "out": results.json, "log": exercise.log}` in JSON (`serve`; a run's
exercise adds `"ready": FILE`, created once the robot is reset and at rest: the grader then starts the node, and
`"ended": FILE`, which the grader creates when the node has ended by itself); it writes
that exercise's results file and check lines, then reads the next line, and ends at the end of its input. Starting
a runner per exercise cost its imports, init_node and connections each time (2-4 s of wall time an exercise on a
loaded machine).

`--wait-service NAME --started FILE` (the grader's first runner, started while the package builds): before anything
else, wait (wall, --wait-s, 60 s by default) until the master lists service NAME (the simulator's, or roscore's
rosout when the suite has no world), create FILE, then connect and serve. The grader starts the student's first
node once FILE exists, so the runner's imports, init_node and ground-truth connection are made while catkin_make
runs instead of after it, and no process of its own is started to ask the master (lab_grader.wait_service). Exit 3
when NAME did not appear in time (nothing served).
"""
import argparse
import json
import sys
import time
from pathlib import Path
from typing import Callable, NamedTuple

from lab_grader.checks import action_checks, run_checks, service_checks
from lab_grader.checks.verdicts import (
    CheckResult,
    Interrupted,
    Verdict,
    results_document,
    summarize_verdicts,
    write_results,
)
from lab_grader.suite_file import SuiteError, load_suite
from lab_grader.wait_service import wait_for_service


class CheckKind(NamedTuple):
    """One kind of check: the CheckSpec field that names its target, how one is run `(check, suite, context,
    found, runs) -> Verdict` (`found`: the services and actions found; `runs`: the recordings of the runs so far)
    and its evidence when it was not run."""

    field: str
    run: Callable
    not_run_evidence: Callable


CHECK_KINDS = (
    CheckKind("run", lambda check, suite, context, found, runs: run_checks.run_run_check(check, suite, context, runs),
              lambda check: run_checks.evidence_of(check, None)),
    CheckKind("action", lambda check, suite, context, found, runs: action_checks.run_action_check(
        check, suite, context, found.get(check.action)), lambda check: action_checks.evidence_of(check, None)),
    CheckKind("service", lambda check, suite, context, found, runs: service_checks.run_check(
        check, suite, context, found.get(check.service)),
        lambda check: service_checks.evidence_of(check, None, None)),
)


def kind_of(check) -> CheckKind:
    return next(kind for kind in CHECK_KINDS if getattr(check, kind.field) is not None)


def not_run_evidence(check):
    return kind_of(check).not_run_evidence(check)


def run_suite(suite, make_context, check_timeout_s=None, log=print):
    """Run every check of `suite` with a context from `make_context()`; returns the results document."""
    wall_start = time.monotonic()
    services = {spec.name: {"expected_type": spec.type, "found": None, "found_by": None, "found_type": None,
                            "note": "not looked up"} for spec in suite.services + suite.actions}
    found = {}
    runs = {}
    results = []
    context = None
    setup_error = None
    interrupted = False
    sim_start = None
    try:
        context = make_context()
        context.wait_until_ready()
        sim_start = context.now()
        if suite.services:
            found.update(context.find_services(suite.services, suite.by_type_grace_s))
        if suite.actions:
            found.update(context.find_actions(suite.actions, suite.by_type_grace_s))
        services = {name: service.as_json() for name, service in found.items()}
        action_names = {action.name for action in suite.actions}
        for name, service in found.items():
            log("{} {}: {}".format("action" if name in action_names else "service", name,
                                   "{} ({}, {})".format(service.found, service.found_by, service.found_type)
                                   if service.found else "not found: {}".format(service.note)))
        log("      {:.1f} s to find them".format(time.monotonic() - wall_start))
    except (Interrupted, KeyboardInterrupt):
        interrupted = True
        setup_error = "the runner was interrupted before the checks started"
    except Exception as error:  # noqa: BLE001 - the results file is written whatever happens
        setup_error = "{}: {}".format(type(error).__name__, error)
        log("setup failed: " + setup_error)

    for number, check in enumerate(suite.checks, start=1):
        if interrupted:
            verdict = Verdict.errored("not run: the runner was interrupted", not_run_evidence(check))
        elif setup_error is not None:
            verdict = Verdict.errored("not run: " + setup_error, not_run_evidence(check))
        else:
            if check_timeout_s is not None:
                check = check._replace(timeout_s=check_timeout_s)
            context.timeline.begin()
            try:
                verdict = kind_of(check).run(check, suite, context, found, runs)
            except (Interrupted, KeyboardInterrupt):
                interrupted = True
                verdict = Verdict.errored("not run: the runner was interrupted", not_run_evidence(check))
            context.timeline.lap("judge")
        result = CheckResult(check.id, check.title, check.weight, verdict, check.kind)
        results.append(result)
        log("[{}/{}] {}".format(number, len(suite.checks), summarize_verdicts([result])[0]))
        if context is not None and setup_error is None and not interrupted:
            log("      " + context.timeline.words())

    timing = {"wall_s": round(time.monotonic() - wall_start, 2)}
    if context is not None and sim_start is not None:
        try:
            timing["sim_s"] = round(context.now() - sim_start, 2)
            context.stop_robot()
        except Exception:  # noqa: BLE001 - the graph may be gone; the results matter more
            pass
    return results_document(suite.name, services, results, complete=not interrupted, timing=timing)


def exercise_suite(suite, node):
    """`suite` cut down to the services, actions and checks of the exercise whose course file is `node`."""
    exercise = next((exercise for exercise in suite.exercises() if exercise.node == node), None)
    if exercise is None:
        raise SuiteError("{}: no exercise is served by a file named {} (files: {})".format(
            suite.path.name, node, ", ".join(suite.nodes)))
    return suite._replace(services=exercise.services, actions=exercise.actions,
                          runs=(exercise.run,) if exercise.run is not None else (),
                          checks=tuple(check for check in suite.checks if check.id in exercise.check_ids))


def serve(suite, make_context, lines, check_timeout_s=None, log=print):
    """Grade one exercise of `suite` per line of `lines` (JSON {"exercise", "out", "log"}, see the module docstring)
    with one context from `make_context()`, made at once (so it is ready when the first line comes). Each
    exercise's results are written to its "out" and its check lines to its "log". Returns at the end of `lines`,
    or once an exercise was interrupted; a line that is not such a command is a SuiteError (nothing else is read:
    its writer would wait for a results file that never comes), a results file that cannot be written an OSError."""
    try:
        context = make_context()
        context.wait_until_ready()
    except (Interrupted, KeyboardInterrupt):
        return
    except Exception as error:  # noqa: BLE001 - each exercise's results say why its checks could not run
        log("setup failed: {}: {}".format(type(error).__name__, error))
        context = error

    def shared_context():
        if isinstance(context, Exception):
            raise context
        return context

    for line in lines:
        try:
            command = json.loads(line)
            exercise, out, log_path = command["exercise"], Path(command["out"]), Path(command["log"])
            ready, ended = command.get("ready"), command.get("ended")
            part = exercise_suite(suite, exercise)
        except (ValueError, KeyError, TypeError) as error:
            raise SuiteError("not a command {{\"exercise\", \"out\", \"log\"}}: {!r} ({}: {})".format(
                line.strip(), type(error).__name__, error)) from None
        if not isinstance(context, Exception):
            context.ready_path, context.ended_path = ready, ended
        with open(log_path, "a") as exercise_log:
            document = run_suite(part, shared_context, check_timeout_s,
                                 log=lambda text: print(text, file=exercise_log, flush=True))
            write_results(out, document)
            print("score {}/{} -> {}".format(document["score"], document["max_score"], out), file=exercise_log,
                  flush=True)
        if not document["complete"]:
            return


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
        prog="run_checks", description="Run a grading suite's checks against the services and actions on this ROS "
        "master (the student's nodes, and tb3_sim if the suite has a world, must be running) and write the results "
        "as JSON.")
    parser.add_argument("--suite", required=True, help="a suite name (suites/<name>.yaml) or a suite file path")
    parser.add_argument("--out", type=Path, help="the results file to write (JSON)")
    parser.add_argument("--serve", action="store_true",
                        help="grade one exercise per line of stdin, {\"exercise\": FILE, \"out\": PATH, \"log\": "
                        "PATH} in JSON, until its end (instead of --out and --exercise)")
    parser.add_argument("--check-timeout", type=positive_seconds, default=None, metavar="S",
                        help="reply timeout of every check, seconds of sim time (default: each check's timeout_s)")
    parser.add_argument("--exercise", metavar="FILE", default=None,
                        help="only the checks of the services and actions that the course's file FILE serves (a "
                        "suite's node:)")
    parser.add_argument("--ground-truth", metavar="SOCKET", default=None,
                        help="tb3_sim's private ground-truth socket (its ~ground_truth_socket); needed when the "
                        "suite has a world: the checks measure the robot through it, never through /odom")
    parser.add_argument("--wait-service", metavar="NAME", default=None,
                        help="first wait until the master lists service NAME (the simulator is up), then create "
                        "--started FILE")
    parser.add_argument("--wait-s", type=positive_seconds, default=60.0, metavar="S",
                        help="how long --wait-service waits, wall seconds (default 60)")
    parser.add_argument("--started", type=Path, default=None, metavar="FILE",
                        help="the file created once --wait-service's service is listed")
    parser.add_argument("--student-home", metavar="DIR", default=None,
                        help="the HOME of the student's nodes: the images a result names (\"~/...\") are looked for "
                        "there")
    # ROS remappings (name:=value) are for rospy, not for us, as rospy.myargv would strip them.
    args = parser.parse_args([arg for arg in argv if ":=" not in arg])
    if args.serve and (args.out is not None or args.exercise is not None):
        parser.error("--serve takes its exercises and results files from stdin: no --out or --exercise")
    if not args.serve and args.out is None:
        parser.error("the following arguments are required: --out (or --serve)")
    if (args.wait_service is None) != (args.started is None):
        parser.error("--wait-service and --started go together")
    return args


def main(argv=None):
    args = parse_args(sys.argv[1:] if argv is None else argv)
    try:
        suite = load_suite(args.suite)
        if args.exercise is not None:
            suite = exercise_suite(suite, args.exercise)
    except SuiteError as error:
        print("run_checks: {}".format(error), file=sys.stderr)
        return 2

    if args.wait_service is not None:
        if not wait_for_service(args.wait_service, args.wait_s):
            print("run_checks: service {} not listed by the master after {:g} s".format(args.wait_service, args.wait_s),
                  file=sys.stderr)
            return 3
        args.started.touch()
    contexts = []

    def make_context():
        # Imported here so that the checks' logic above imports (and is unit-tested) without rospy.
        from lab_grader.checks.context import GradingContext
        contexts.append(GradingContext(robot=suite.world is not None, ground_truth=args.ground_truth,
                                       student_home=args.student_home))
        return contexts[-1]

    if args.serve:
        try:
            serve(suite, make_context, sys.stdin, args.check_timeout, log=lambda line: print(line, flush=True))
        except KeyboardInterrupt:
            pass     # stopped while waiting for a command: every results file asked for so far is written
        except SuiteError as error:
            print("run_checks: {}".format(error), file=sys.stderr)
            return 2
        except OSError as error:
            print("run_checks: cannot write a results file: {}".format(error), file=sys.stderr)
            return 1
        finally:
            for context in contexts:
                context.shutdown()
        return 0
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


if __name__ == "__main__":   # the grader runs it so, without rosrun's package search
    sys.exit(main())
