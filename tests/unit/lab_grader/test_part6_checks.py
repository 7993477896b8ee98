"""The part6 suite and what run checks judge: the shipped suite loads (two runs, each in its own course world); the
run keys are validated, naming the file and key; `judge_run` finds the stops after the first motion and what each
faced, and measures progress along a line of cubic Beziers, its mean and largest distance, and when the robot left
it; a run is recorded once and judged by every check of it."""
import copy
import math

import pytest
import yaml

from lab_grader.checks import runner
from lab_grader.checks.motion import Sample
from lab_grader.checks.run_checks import RunObservation, bezier_points, judge_run, run_run_check, stops
from lab_grader.checks.verdicts import ERROR, FAIL, INTERFERENCE, PASS, InterferenceError
from lab_grader.suite_file import Range, RunSpec, SuiteError, load_suite

from .test_suite_file import SUITES_DIR

SUITE = load_suite(SUITES_DIR / "part6.yaml")
CHECKS = {check.id: check for check in SUITE.checks}
PILLARS = {"red": (0.6, 0.6), "green": (-0.6, 0.6), "turquoise": (-0.6, -0.6), "blue": (0.6, -0.6)}
RATE_HZ = 30.0


def test_the_shipped_part6_suite_grades_each_run_in_its_course_world():
    assert SUITE.max_score == 100 and not SUITE.services and not SUITE.actions
    colour, line = SUITE.exercises()
    assert (colour.node, colour.check_ids) == ("colour_search.py", ("colour_search_blue",
                                                                     "colour_search_every_pillar"))
    assert SUITE.world_of(colour) == "tuos_simulations/worlds/coloured_pillars.yaml"
    assert SUITE.launch_args(colour) == ["camera_rate:=10"]
    assert (line.node, line.check_ids) == ("line_follower.py", ("line_progress", "line_mean_distance",
                                                                 "line_never_leaves"))
    assert SUITE.world_of(line) == "tuos_simulations/worlds/line_following.yaml"
    assert SUITE.launch_args(line) == ["camera_rate:=10", "x_pos:=2.4", "y_pos:=-2.5", "yaw:=3.14"]
    every = CHECKS["colour_search_every_pillar"].expect.stops_facing
    assert every.faces == ("red", "green", "turquoise", "blue") and every.landmarks == PILLARS
    assert CHECKS["colour_search_blue"].expect.stops_facing.faces == ("blue",)
    track = CHECKS["line_progress"].expect.line
    points, arc = bezier_points(track.points)
    assert arc[-1] == pytest.approx(19.59, abs=0.02)          # the course's 19.59 m line
    assert tuple(points[0]) == pytest.approx((2.3797, -2.5004)) and track.progress_m.min == 3.5


def load_changed(tmp_path, change):
    data = copy.deepcopy(yaml.safe_load((SUITES_DIR / "part6.yaml").read_text()))
    change(data)
    path = tmp_path / "part6.yaml"
    path.write_text(yaml.safe_dump(data))
    return load_suite(path)


def _set(path, value):
    def change(data):
        target = data
        for key in path[:-1]:
            target = target[key]
        target[path[-1]] = value
    return change


@pytest.mark.parametrize("change, message", [
    (_set(("runs", 0, "duration_s"), 0), r"part6.yaml: runs\[0\]\.duration_s: must be > 0"),
    (_set(("runs", 0, "speed"), 1), r"runs\[0\]\.speed: unknown key"),
    (_set(("checks", 0, "run"), "other.py"), r"checks\[0\]\.run: 'other.py' is not one of the suite's runs"),
    (_set(("checks", 0, "expect"), {}), r"checks\[0\]\.expect: expected one of stops_facing, line"),
    (_set(("checks", 0, "expect", "stops_facing", "faces"), ["purple"]),
     r"stops_facing\.faces\[0\]: 'purple' is not one of the landmarks"),
    (_set(("checks", 0, "expect", "stops_facing", "landmarks", "red"), [0.6]),
     r"landmarks\.red: expected a point \[x, y\] in m"),
    (_set(("checks", 2, "expect", "line", "points"), [[0, 0], [1, 1]]),
     r"line\.points: expected a start point and 3 more per cubic Bezier, got 2 points"),
    (_set(("checks", 2, "expect", "line", "leave_m"), -1), r"line\.leave_m: must be > 0"),
])
def test_bad_run_keys_are_named(tmp_path, change, message):
    with pytest.raises(SuiteError, match=message):
        load_changed(tmp_path, change)


def test_a_run_without_any_world_is_refused(tmp_path):
    def no_world(data):
        del data["world"]
        del data["simulator_args"]
    with pytest.raises(SuiteError, match=r"runs\[0\]: a run needs a robot: the suite has no world"):
        load_changed(tmp_path, no_world)


# ---- judging one recording -------------------------------------------------------------------------------------------

def spin(start_s, duration_s, x=0.0, y=0.0, yaw=0.0, w=0.0, v=0.0):
    """Samples at RATE_HZ: turning at w (rad/s) and driving at v (m/s) along the heading, from a pose."""
    samples = []
    for i in range(int(round(duration_s * RATE_HZ))):
        dt = i / RATE_HZ
        heading = yaw + w * dt
        samples.append(Sample(start_s + dt, x + v * dt * math.cos(yaw), y + v * dt * math.sin(yaw), heading, v, w))
    return samples


def turn_and_stop(*stops_deg, start_s=5.0, rest_s=2.0, w=0.5):
    """At rest until start_s, then turning counter-clockwise at w and resting rest_s at each heading (deg)."""
    samples = spin(0.0, start_s)
    heading, t = 0.0, start_s
    for target in stops_deg:
        turn_s = math.radians(target) - heading
        samples += spin(t, turn_s / w, yaw=heading, w=w)
        t, heading = t + turn_s / w, math.radians(target)
        samples += spin(t, rest_s, yaw=heading)
        t += rest_s
    return tuple(samples)


def colour_check(faces):
    check = CHECKS["colour_search_every_pillar"]
    wanted = check.expect.stops_facing._replace(faces=tuple(faces))
    return check._replace(expect=check.expect._replace(stops_facing=wanted))


def test_stops_after_the_first_motion_face_the_pillars_within_the_tolerance():
    samples = turn_and_stop(45, 135, 225, 315 + 11)      # blue 11 deg off: within 12
    assert [round(stop.start_s - 5.0) for stop in stops(samples, 1.0)][:1] == [2]   # the rest before is no stop
    verdict = judge_run(colour_check(["red", "green", "turquoise", "blue"]), RunObservation(0.0, samples))
    assert verdict.verdict == PASS, verdict.reason
    assert "facing blue (-11.0 deg)" in verdict.reason
    assert [stop["nearest"] for stop in verdict.evidence["stops"]] == ["red", "green", "turquoise", "blue"]


def test_stopping_on_the_wrong_pillar_fails_naming_what_it_faced():
    verdict = judge_run(colour_check(["blue"]), RunObservation(0.0, turn_and_stop(45)))
    assert verdict.verdict == FAIL
    assert verdict.reason == ("expected to stop (still for 1 s) facing blue (the bearing to its centre within 12 deg "
                              "of the heading), it stopped 1 time: at 6.6 s facing red (+0.0 deg)")


def test_a_robot_that_never_stops_or_never_moves_fails_saying_so():
    spinning = tuple(spin(0.0, 1.0) + spin(1.0, 30.0, w=0.5))
    verdict = judge_run(colour_check(["blue"]), RunObservation(0.0, spinning))
    assert verdict.verdict == FAIL and verdict.reason.endswith("it never stopped for 1 s after it first moved")
    still = judge_run(colour_check(["blue"]), RunObservation(0.0, tuple(spin(0.0, 30.0))))
    assert still.verdict == FAIL and still.reason.endswith("the robot never moved")
    between = judge_run(colour_check(["blue"]), RunObservation(0.0, turn_and_stop(290)))   # 25 deg short of blue
    assert between.verdict == FAIL and "facing nothing within 12 deg (nearest blue at +25.0 deg)" in between.reason


STRAIGHT_LINE = ((0.0, 0.0), (1.0, 0.0), (2.0, 0.0), (3.0, 0.0))


def line_check(**ranges):
    check = CHECKS["line_progress"]
    line = check.expect.line._replace(**dict(dict(points=STRAIGHT_LINE, progress_m=None), **ranges))
    return check._replace(expect=check.expect._replace(line=line))


def test_progress_along_the_line_counts_until_the_robot_first_leaves_it():
    # 1 s at rest, then 0.1 m/s along the line 0.02 m to its left for 10 s, then off at 30 deg for 10 s
    samples = spin(0.0, 1.0, y=0.02) + spin(1.0, 10.0, y=0.02, v=0.1)
    samples += spin(11.0, 10.0, x=1.0, y=0.02, yaw=math.radians(30), v=0.1)
    verdict = judge_run(line_check(progress_m=Range(1.5, None)), RunObservation(0.0, tuple(samples)))
    assert verdict.verdict == FAIL
    line = verdict.evidence["line"]
    assert line["progress_m"] == pytest.approx(1.225, abs=0.01)   # 0.15 m off after 0.26 m at 30 deg: x = 1.225
    assert line["left_after_s"] == pytest.approx(13.6, abs=0.1)
    assert verdict.reason.startswith("expected to progress at least 1.5 m along the line before leaving it, it "
                                     "progressed 1.22 m (it got more than 0.15 m from it 13.6 s after the reset)")
    close = judge_run(line_check(mean_distance_m=Range(None, 0.05), max_distance_m=Range(None, 0.15)),
                      RunObservation(0.0, tuple(samples[:330])))
    assert close.verdict == PASS, close.reason
    assert close.evidence["line"]["mean_distance_m"] == pytest.approx(0.02, abs=1e-3)
    far = judge_run(line_check(max_distance_m=Range(None, 0.15)), RunObservation(0.0, tuple(samples)))
    assert far.verdict == FAIL
    assert "expected its largest distance to the line to be at most 0.15 m, it got" in far.reason


class FakeContext:
    def __init__(self, observation):
        self.observation, self.recorded = observation, 0

    def prepare(self, still_timeout_s):
        pass

    def observe_run(self, duration_s, start_s):
        self.recorded += 1
        if isinstance(self.observation, Exception):
            raise self.observation
        return self.observation


def test_a_run_is_recorded_once_for_all_its_checks_and_its_troubles_reach_each():
    context = FakeContext(RunObservation(0.0, turn_and_stop(45, 135, 225, 315)))
    runs = {}
    verdicts = [runner.kind_of(check).run(check, SUITE, context, {}, runs) for check in SUITE.checks[:2]]
    assert [v.verdict for v in verdicts] == [PASS, PASS] and context.recorded == 1
    interfered = FakeContext(InterferenceError(["paused physics"]))
    runs = {}
    assert [run_run_check(check, SUITE, interfered, runs).verdict for check in SUITE.checks[:2]] == [
        INTERFERENCE, INTERFERENCE]
    assert interfered.recorded == 1
    broken = run_run_check(SUITE.checks[0], SUITE, FakeContext(RuntimeError("the simulator stopped")), {})
    assert broken.verdict == ERROR and broken.reason == "RuntimeError: the simulator stopped"
    assert judge_run(SUITE.checks[0], RunObservation(0.0, ())).verdict == ERROR


def test_the_default_start_allowance_is_a_minute_of_sim_time():
    assert RunSpec("x.py", 10.0).start_s == 60.0 and SUITE.runs[0].start_s == 60.0
