"""Run checks: a node that serves nothing but drives the robot (Part 6's colour search and line follower), judged on
one recording of the robot's true motion (plain Python; the context does the ROS part).

The grader resets the robot, lets it come to rest, then starts the student's node alone; the context records the
ground truth from the reset until the run's `duration_s` of sim time after the robot first moved (the node's
start-up is not counted: it depends on the machine's load) into a `RunObservation`, which every check of that run
judges (`judge_run`). Each kind of expectation is one function in RUN_JUDGES, `(expect, observation) -> (problems,
summary, evidence)`; a new kind is one function, one parser in suite_file.RUN_EXPECT_PARSERS and one line in each
registry.

- stops_facing: a stop is a stretch of still samples (motion.is_still) lasting `still_s` or more after the robot
  first moved (the rest before the node started is not a stop). At a stop the robot faces a landmark when the
  bearing from its true position and heading to the landmark's centre is within `tolerance_deg`; every name in
  `faces` must be faced at some stop. The reason names what each stop faced (the nearest landmark by bearing).
- line: the line is a chain of cubic Beziers sampled every LINE_STEP_M or less. From the first motion on, each true
  position's distance to the line and the arc length of its nearest point are measured: progress is the furthest
  arc length reached (from where the robot's first position projects) before the robot first got more than
  `leave_m` from the line; mean and largest distance are over every sample from the first motion to the end.

Verdicts: error when nothing was recorded (the simulator stopped) or the robot could not be prepared; interference
as for the other checks; fail when an expectation does not hold (the reason lists each); pass otherwise.
"""
import math
from typing import List, NamedTuple, Optional, Tuple

import numpy as np

from lab_grader.checks.motion import Sample, is_still, thin, wrap_angle
from lab_grader.checks.verdicts import InterferenceError, Interrupted, Verdict

LINE_STEP_M = 0.005


class RunObservation(NamedTuple):
    """The ground truth from the reset (`started_s`, sim s) to the end of the run's recording."""

    started_s: float
    samples: Tuple[Sample, ...]
    interference: Tuple[str, ...] = ()


class Stop(NamedTuple):
    start_s: float
    end_s: float
    x: float
    y: float
    yaw: float


def after_first_motion(samples):
    """The samples from the first one that moves on (empty when the robot never moved)."""
    moving = next((index for index, sample in enumerate(samples) if not is_still(sample)), None)
    return () if moving is None else tuple(samples[moving:])


def stops(samples, still_s) -> List[Stop]:
    """The stretches of still samples lasting `still_s` or more after the first motion, in order."""
    found, run = [], []
    for sample in after_first_motion(samples) + (None,):
        if sample is not None and is_still(sample):
            run.append(sample)
            continue
        if run and run[-1].t - run[0].t >= still_s:
            found.append(Stop(run[0].t, run[-1].t, run[0].x, run[0].y, run[0].yaw))
        run = []
    return found


def bearing_deg(stop, point):
    """Degrees from the robot's heading at `stop` to `point` (x, y), counter-clockwise positive."""
    return math.degrees(wrap_angle(math.atan2(point[1] - stop.y, point[0] - stop.x) - stop.yaw))


def nearest_landmark(stop, landmarks):
    """(name, bearing in deg) of the landmark closest to the robot's heading at `stop`."""
    return min(((name, bearing_deg(stop, point)) for name, point in landmarks.items()), key=lambda nb: abs(nb[1]))


def stops_facing_judge(expect, observation):
    found = stops(observation.samples, expect.still_s)
    facing = [nearest_landmark(stop, expect.landmarks) for stop in found]
    evidence = {"stops": [{"after_s": round(stop.start_s - observation.started_s, 2),
                           "still_s": round(stop.end_s - stop.start_s, 2), "nearest": name,
                           "bearing_deg": round(bearing, 1)} for stop, (name, bearing) in zip(found, facing)]}
    faced = {name for name, bearing in facing if abs(bearing) <= expect.tolerance_deg}
    stops_words = "; ".join("at {:.1f} s {}".format(
        stop.start_s - observation.started_s,
        "facing {} ({:+.1f} deg)".format(name, bearing) if abs(bearing) <= expect.tolerance_deg
        else "facing nothing within {:g} deg (nearest {} at {:+.1f} deg)".format(expect.tolerance_deg, name, bearing))
        for stop, (name, bearing) in zip(found, facing))
    if not after_first_motion(observation.samples):
        happened = "the robot never moved"
    elif not found:
        happened = "it never stopped for {:g} s after it first moved".format(expect.still_s)
    else:
        happened = "it stopped {} time{}: {}".format(len(found), "" if len(found) == 1 else "s", stops_words)
    missing = [name for name in expect.faces if name not in faced]
    if missing:
        return (["expected to stop (still for {:g} s) facing {} (the bearing to its centre within {:g} deg of the "
                 "heading), {}".format(expect.still_s, " and ".join(missing), expect.tolerance_deg, happened)],
                None, evidence)
    return [], happened, evidence


def bezier_points(points, step_m=LINE_STEP_M):
    """(N, 2) points along the chain of cubic Beziers (start, then control 1, control 2, end per curve), under
    `step_m` apart, and the (N,) arc length at each."""
    controls = np.asarray(points, dtype=float)
    pieces = []
    for index in range(0, len(controls) - 1, 3):
        p0, c1, c2, p1 = controls[index:index + 4]
        hull = np.linalg.norm(c1 - p0) + np.linalg.norm(c2 - c1) + np.linalg.norm(p1 - c2)
        t = np.linspace(0.0, 1.0, max(2, int(math.ceil(hull / step_m)) + 1))[:, None]
        curve = (1 - t) ** 3 * p0 + 3 * (1 - t) ** 2 * t * c1 + 3 * (1 - t) * t ** 2 * c2 + t ** 3 * p1
        pieces.append(curve if not pieces else curve[1:])
    line = np.vstack(pieces)
    arc = np.concatenate(([0.0], np.cumsum(np.linalg.norm(np.diff(line, axis=0), axis=1))))
    return line, arc


class LineTrack(NamedTuple):
    distance_m: np.ndarray    # each sample's distance to the line (from the first motion on)
    arc_m: np.ndarray         # the arc length of each sample's nearest point on the line
    progress_m: float
    left_after_s: Optional[float]   # when it first got more than leave_m from the line (s since the reset)


def track(expect, observation) -> Optional[LineTrack]:
    samples = after_first_motion(observation.samples)
    if not samples:
        return None
    line, arc = bezier_points(expect.points)
    positions = np.array([(sample.x, sample.y) for sample in samples])
    distances, nearest = np.empty(len(positions)), np.empty(len(positions), dtype=int)
    for start in range(0, len(positions), 256):   # a block at a time: samples x line points stays small
        block = positions[start:start + 256]
        squared = ((block[:, None, :] - line[None, :, :]) ** 2).sum(axis=2)
        nearest[start:start + 256] = squared.argmin(axis=1)
        distances[start:start + 256] = np.sqrt(squared.min(axis=1))
    arcs = arc[nearest]
    off = np.flatnonzero(distances > expect.leave_m)
    on_line = arcs if not off.size else arcs[:off[0]]
    progress = float(on_line.max() - arcs[0]) if on_line.size else 0.0
    left = None if not off.size else samples[off[0]].t - observation.started_s
    return LineTrack(distances, arcs, max(progress, 0.0), left)


def line_judge(expect, observation):
    followed = track(expect, observation)
    if followed is None:
        return (["expected to drive along the line, the robot never moved"], None, {"line": None})
    mean, largest = float(followed.distance_m.mean()), float(followed.distance_m.max())
    evidence = {"line": {"progress_m": round(followed.progress_m, 3), "mean_distance_m": round(mean, 4),
                         "max_distance_m": round(largest, 4),
                         "left_after_s": None if followed.left_after_s is None else round(followed.left_after_s, 2)}}
    left = ("it never got more than {:g} m from it".format(expect.leave_m) if followed.left_after_s is None
            else "it got more than {:g} m from it {:.1f} s after the reset".format(expect.leave_m,
                                                                                  followed.left_after_s))
    problems = []
    if expect.progress_m is not None and not expect.progress_m.contains(followed.progress_m):
        problems.append("expected to progress {} along the line before leaving it, it progressed {:.2f} m ({})".format(
            expect.progress_m.describe("m"), followed.progress_m, left))
    if expect.mean_distance_m is not None and not expect.mean_distance_m.contains(mean):
        problems.append("expected a mean distance to the line of {}, it was {:.3f} m".format(
            expect.mean_distance_m.describe("m"), mean))
    if expect.max_distance_m is not None and not expect.max_distance_m.contains(largest):
        problems.append("expected its largest distance to the line to be {}, it got {:.3f} m away".format(
            expect.max_distance_m.describe("m"), largest))
    summary = "progressed {:.2f} m along the line, mean distance {:.3f} m, largest {:.3f} m; {}".format(
        followed.progress_m, mean, largest, left)
    return problems, summary, evidence


RUN_JUDGES = {"stops_facing": stops_facing_judge, "line": line_judge}   # suite_file.RunExpectation's fields


def evidence_of(check, observation):
    evidence = {"run": check.run, "trajectory": []}
    if observation is not None and observation.samples:
        evidence["trajectory"] = thin(observation.samples, observation.started_s)
        evidence["recorded_s"] = round(observation.samples[-1].t - observation.started_s, 2)
    return evidence


def judge_run(check, observation) -> Verdict:
    """The verdict on one RunObservation of a run `check` (suite_file.CheckSpec with `run`)."""
    evidence = evidence_of(check, observation)
    if observation.interference:
        return Verdict.interfered(observation.interference, evidence)
    if not observation.samples:
        return Verdict.errored("no ground truth was recorded during the run: is the simulator running?", evidence)
    problems, summaries = [], []
    for kind, judge in RUN_JUDGES.items():
        wanted = getattr(check.expect, kind)
        if wanted is None:
            continue
        found, summary, extra = judge(wanted, observation)
        problems += found
        evidence.update(extra)
        if summary:
            summaries.append(summary)
    if problems:
        return Verdict.failed("; ".join(problems), evidence)
    return Verdict.passed("; ".join(summaries), evidence)


def run_run_check(check, suite, context, observations) -> Verdict:
    """Judge `check` on its run's recording, made once per run: the first check of a run asks the context to prepare
    the robot, let the grader start the node and record; `observations` keeps the recording (or what went wrong)
    for the run's other checks. Every exception becomes an error verdict (Interrupted is passed on)."""
    if check.run not in observations:
        try:
            run = next(spec for spec in suite.runs if spec.node == check.run)
            context.prepare(suite.still_timeout_s)
            observations[check.run] = context.observe_run(run.duration_s, run.start_s)
        except Interrupted:
            raise
        except Exception as error:  # noqa: BLE001 - a check never crashes the runner
            observations[check.run] = error
    recorded = observations[check.run]
    if isinstance(recorded, InterferenceError):
        return Verdict.interfered(recorded.findings, evidence_of(check, None))
    if isinstance(recorded, Exception):
        return Verdict.errored("{}: {}".format(type(recorded).__name__, recorded), evidence_of(check, None))
    return judge_run(check, recorded)
