"""Verdicts and scoring: points by weight, the results file (strict JSON, written atomically), the judgement of
scripted observations against the Week 4 suite's expectations, and a run against a fake context in which
checks raise, time out or are interrupted: the results are always complete and written; and interference (a
submission tampering with the measurement) outranking every other verdict."""
import json
import math
import os
import re

import pytest

from lab_grader.checks import interference, runner, service_checks
from lab_grader.checks.fields import same_value
from lab_grader.checks.ground_truth import Seen, WorldChange
from lab_grader.checks.motion import Observation
from lab_grader.checks.timeline import Timeline
from lab_grader.checks.verdicts import (
    ERROR,
    FAIL,
    INTERFERENCE,
    PASS,
    RESULTS_SCHEMA,
    CheckError,
    CheckResult,
    FoundService,
    InterferenceError,
    Interrupted,
    Verdict,
    json_safe,
    one_line,
    results_document,
    score,
    write_results,
)
from lab_grader.suite_file import SuiteError, load_suite

from .test_motion import drive
from .test_suite_file import SUITES_DIR

SUITE = load_suite(SUITES_DIR / "week4.yaml")
CHECKS = {check.id: check for check in SUITE.checks}


def result(check_id, verdict, weight):
    return CheckResult(check_id, check_id, weight, Verdict(verdict, "why", {}))


def test_score_sums_the_weights_of_passed_checks_only():
    results = [result("a", PASS, 16), result("b", FAIL, 6), result("c", ERROR, 8), result("d", PASS, 2.5)]
    assert score(results) == (18.5, 32.5)
    assert score([result("a", PASS, 16), result("b", PASS, 4)]) == (20, 20)
    assert isinstance(score([result("a", PASS, 16.0)])[0], int)
    assert score([]) == (0, 0)


def test_reasons_are_one_line_and_bounded():
    assert one_line("a\nb \t c") == "a b c"
    assert len(one_line("x" * 1000)) == 400 and one_line("x" * 1000).endswith("...")
    assert Verdict.failed("expected\nthis").reason == "expected this"


def test_json_safe_turns_non_finite_floats_into_strings():
    assert json_safe({"a": math.nan, "b": [math.inf, -math.inf, 1.5], 3: (1, 2)}) == {
        "a": "nan", "b": ["inf", "-inf", 1.5], "3": [1, 2]}


def test_the_results_document_has_the_schema():
    services = {"/move_service": {"expected_type": "tuos_msgs/SetBool", "found": "/move_service",
                                  "found_by": "by name", "found_type": "tuos_msgs/SetBool", "note": None}}
    document = results_document("week4", services, [result("move_true", PASS, 16), result("move_false", FAIL, 6)],
                                timing={"wall_s": 1.0})
    assert document["schema"] == RESULTS_SCHEMA and document["suite"] == "week4"
    assert document["score"] == 16 and document["max_score"] == 22 and document["complete"] is True
    assert document["services"] == services
    assert document["checks"][0] == {"id": "move_true", "title": "move_true", "kind": "required", "weight": 16,
                                     "verdict": "pass", "reason": "why", "evidence": {}}


def test_write_results_is_atomic_strict_json_and_leaves_no_temporary_file(tmp_path):
    out = tmp_path / "deeper" / "r.json"
    write_results(out, {"value": math.nan, "checks": []})
    assert json.loads(out.read_text()) == {"value": "nan", "checks": []}
    write_results(out, {"value": 2})
    assert json.loads(out.read_text()) == {"value": 2}
    assert os.listdir(out.parent) == ["r.json"]


def test_a_failed_write_keeps_the_old_file_and_no_temporary_one(tmp_path):
    out = tmp_path / "r.json"
    write_results(out, {"value": 1})
    with pytest.raises(TypeError):
        write_results(out, {"value": object()})
    assert json.loads(out.read_text()) == {"value": 1}
    assert os.listdir(tmp_path) == ["r.json"]


# ---- judging observations against the Week 4 suite ------------------------------------------------------------------

T0 = 100.0


def observe(commands, reply, error=None, front=None, reply_after=None):
    """An Observation of a robot following `commands` [(s, v, w), ...] from T0, replying at the end of the motion
    (or `reply_after` s after the request), recorded until 1 s after the reply."""
    samples = drive(commands, t0=T0)
    motion_s = sum(duration for duration, _v, _w in commands)
    replied = None if error else T0 + (reply_after if reply_after is not None else motion_s - 1.0)
    return Observation(request={}, reply=reply, error=error, sent_s=T0, replied_s=replied, samples=tuple(samples),
                       front_distance_m=front, front_measured=front is not None)


def judge(check_id, observation):
    return service_checks.judge(CHECKS[check_id], observation, SUITE.settle_s)


def test_the_reference_move_passes():
    verdict = judge("move_true", observe([(5.0, 0.1, 0), (1.0, 0, 0)], {"response_signal": True,
                                                                         "response_message": "done"}))
    assert verdict.verdict == PASS, verdict.reason
    assert "drove forwards 0.500 m" in verdict.reason
    evidence = verdict.evidence
    assert evidence["reply"] == {"response_signal": True, "response_message": "done"}
    assert evidence["motion"]["forward_m"] == pytest.approx(0.5, abs=0.005)
    assert evidence["motion"]["still_at_end"] is True
    assert 0 < len(evidence["trajectory"]) <= 400 and evidence["trajectory"][0][0] == 0.0
    assert evidence["reply_after_s"] == pytest.approx(5.0)


def test_a_move_backwards_fails_naming_the_direction():
    verdict = judge("move_true", observe([(5.0, -0.1, 0), (1.0, 0, 0)], {"response_signal": True,
                                                                          "response_message": ""}))
    assert verdict.verdict == FAIL
    assert "expected to drive forwards 0.35..0.6 m along its initial heading, it drove backwards 0.500 m" \
        in verdict.reason


def test_a_move_that_is_too_short_and_never_stops_lists_both():
    verdict = judge("move_true", observe([(3.0, 0.1, 0)], {"response_signal": True, "response_message": ""},
                                         reply_after=2.0))
    assert verdict.verdict == FAIL
    assert "it drove forwards 0.29" in verdict.reason
    assert "expected the motion to last 4..5.5 s of sim time, it was still moving" in verdict.reason
    assert "expected the robot to be still 1 s after the reply, it was moving" in verdict.reason


def test_the_course_templates_whole_second_timing_passes():
    """`while rospy.get_rostime().secs - start.secs < 5` started at x.9 s stops after 4.1 s (0.41 m at 0.1 m/s),
    a 2 s one after 1.1 s: what the course's own solution does, so both pass."""
    five = judge("move_true", observe([(4.1, 0.1, 0), (1.0, 0, 0)], {"response_signal": True,
                                                                      "response_message": ""}))
    assert five.verdict == PASS, five.reason
    two = judge("timed_fwd", observe([(1.1, 0.1, 0), (1.0, 0, 0)], {"success": True}))
    assert two.verdict == PASS, two.reason
    too_short = judge("timed_fwd", observe([(0.9, 0.1, 0), (1.0, 0, 0)], {"success": True}))
    assert too_short.verdict == FAIL and "expected the motion to last 1..2.5 s" in too_short.reason


def test_a_wrong_reply_fails_even_when_the_motion_is_right():
    verdict = judge("move_true", observe([(5.0, 0.1, 0), (1.0, 0, 0)], {"response_signal": False,
                                                                         "response_message": ""}))
    assert verdict.verdict == FAIL and "expected response_signal True, it replied False" in verdict.reason


def test_reply_kinds_are_strict():
    assert not same_value(1, True) and same_value(True, True)
    assert same_value(0.4000000059604645, 0.4) and not same_value("0.4", 0.4)


def test_refusals_pass_without_motion_and_fail_with_it():
    still = judge("timed_invalid_word", observe([(1.5, 0, 0)], {"success": False}))
    assert still.verdict == PASS, still.reason and "did not move" in still.reason
    moved = judge("timed_invalid_word", observe([(2.0, 0.1, 0), (1.0, 0, 0)], {"success": False}))
    assert moved.verdict == FAIL
    assert "expected to stay within 0.01 m of where it started, it got 0.2" in moved.reason


def test_turns_are_judged_by_direction():
    left = judge("timed_left", observe([(3.0, 0, 0.3), (1.0, 0, 0)], {"success": True}))
    assert left.verdict == PASS, left.reason
    wrong_way = judge("timed_left", observe([(3.0, 0, -0.3), (1.0, 0, 0)], {"success": True}))
    assert wrong_way.verdict == FAIL
    assert "expected to turn counter-clockwise at least 5 deg, it turned clockwise" in wrong_way.reason


def test_timed_back_wants_backwards_and_the_right_duration():
    right = judge("timed_back", observe([(2.0, -0.1, 0), (1.0, 0, 0)], {"success": True}))
    assert right.verdict == PASS, right.reason
    too_long = judge("timed_back", observe([(3.0, -0.1, 0), (1.0, 0, 0)], {"success": True}))
    assert too_long.verdict == FAIL and "expected the motion to last 1..2.5 s" in too_long.reason
    forwards = judge("timed_back", observe([(2.0, 0.1, 0), (1.0, 0, 0)], {"success": True}))
    assert "expected to drive backwards at least 0.05 m along its initial heading, it drove forwards" \
        in forwards.reason


def test_the_approach_is_judged_on_the_reply_text_and_the_front_lidar():
    stopped = {"response_message": "Stopped: the closest object ahead is 0.393 m away"}
    good = judge("approach_stops_at_distance", observe([(9.0, 0.1, 0), (1.0, 0, 0)], stopped, front=0.39))
    assert good.verdict == PASS, good.reason
    assert good.evidence["front_distance_m"] == 0.39
    far = judge("approach_stops_at_distance", observe([(5.0, 0.1, 0), (1.0, 0, 0)], stopped, front=0.8))
    assert far.verdict == FAIL and "expected the front LiDAR to read 0.35..0.45 m once still, it read 0.800 m" \
        in far.reason
    silent = judge("approach_stops_at_distance", observe([(9.0, 0.1, 0), (1.0, 0, 0)], {"response_message": "ok"},
                                                         front=0.4))
    assert silent.verdict == FAIL and "to match" in silent.reason


def test_no_reply_is_an_error_with_the_motion_as_evidence():
    verdict = judge("timed_fwd", observe([(3.0, 0, 0)], None, error="no reply within 10 s of sim time"))
    assert verdict.verdict == ERROR and verdict.reason == "no reply within 10 s of sim time"
    assert verdict.evidence["reply"] is None and verdict.evidence["motion"] is not None


def test_no_odometry_is_an_error():
    empty = Observation({}, {"success": True}, None, T0, T0 + 1, ())
    verdict = judge("timed_fwd", empty)
    assert verdict.verdict == ERROR and "no /odom" in verdict.reason


# ---- a whole run against a fake context ------------------------------------------------------------------------------

class FakeContext:
    """Moves the robot as the reference would for move_service, raises for timed_move_service, and has no
    approach_service; `interrupt_at` raises Interrupted at that call."""

    def __init__(self, interrupt_at=None):
        self.timeline = Timeline()
        self.calls = 0
        self.interrupt_at = interrupt_at
        self.stopped = 0

    def wait_until_ready(self):
        pass

    def now(self):
        return T0

    def find_services(self, specs, grace):
        found = {"/move_service": "/move_service", "/timed_move_service": "/timed_move_service"}
        return {spec.name: FoundService(spec.name, spec.type, found.get(spec.name),
                                        "by name" if spec.name in found else None, spec.type,
                                        None if spec.name in found else "no service named " + spec.name)
                for spec in specs}

    def prepare(self, still_timeout_s):
        self.calls += 1
        if self.calls == self.interrupt_at:
            raise Interrupted("stop")
        if self.calls == 3:
            raise CheckError("the robot did not come to rest")

    def observe(self, service, request, timeout_s, settle_s, measure_front=False):
        if service.found == "/timed_move_service":
            raise RuntimeError("boom")
        if request["request_signal"]:
            return observe([(5.0, 0.1, 0), (1.0, 0, 0)], {"response_signal": True, "response_message": ""})
        return observe([(1.0, 0, 0)], {"response_signal": False, "response_message": ""})

    def stop_robot(self):
        self.stopped += 1


def test_a_run_turns_every_problem_into_an_error_verdict_and_scores_the_rest():
    document = runner.run_suite(SUITE, FakeContext, log=lambda line: None)
    verdicts = {check["id"]: check for check in document["checks"]}
    assert len(verdicts) == 17 and document["complete"] is True
    assert verdicts["move_true"]["verdict"] == PASS and verdicts["move_false"]["verdict"] == PASS
    assert verdicts["timed_fwd"]["verdict"] == ERROR
    assert verdicts["timed_fwd"]["reason"] == "CheckError: the robot did not come to rest"
    assert verdicts["timed_back"]["reason"] == "RuntimeError: boom"
    approach = verdicts["approach_stops_at_distance"]
    assert approach["verdict"] == ERROR
    assert approach["reason"] == "service /approach_service not found: no service named /approach_service"
    assert approach["evidence"]["request"] == {"approach_distance": 0.4, "approach_velocity": 0.1}
    assert document["score"] == 22 and document["max_score"] == 100
    assert document["services"]["/approach_service"]["found"] is None
    json.dumps(document, allow_nan=False)     # strict JSON: the NaN requests are strings
    assert verdicts["approach_distance_nan"]["evidence"]["request"]["approach_distance"] == "nan"


def test_an_interrupted_run_still_lists_every_check():
    document = runner.run_suite(SUITE, lambda: FakeContext(interrupt_at=2), log=lambda line: None)
    assert document["complete"] is False and len(document["checks"]) == 17
    assert document["checks"][0]["verdict"] == PASS
    assert all(check["reason"] == "not run: the runner was interrupted" for check in document["checks"][1:])


def test_a_context_that_cannot_start_errors_every_check():
    def broken():
        raise CheckError("no /clock after 30 s")
    document = runner.run_suite(SUITE, broken, log=lambda line: None)
    assert document["score"] == 0 and document["complete"] is True
    assert {check["verdict"] for check in document["checks"]} == {ERROR}
    assert document["checks"][0]["reason"] == "not run: CheckError: no /clock after 30 s"


def test_check_timeout_overrides_every_check():
    seen = []

    class Recording(FakeContext):
        def observe(self, service, request, timeout_s, settle_s, measure_front=False):
            seen.append(timeout_s)
            return super().observe(service, request, timeout_s, settle_s, measure_front)

    document = runner.run_suite(SUITE, Recording, check_timeout_s=4.0, log=lambda line: None)
    assert seen and set(seen) == {4.0}
    assert document["checks"][0]["evidence"]["timeout_s"] == 4.0


def serve_command(tmp_path, exercise, number):
    return json.dumps({"exercise": exercise, "out": str(tmp_path / "checks-{}.json".format(number)),
                       "log": str(tmp_path / "checks-{}.log".format(number))})


def test_serve_grades_exercise_after_exercise_with_one_context(tmp_path):
    """The grader's one runner per submission: one context, made before the first command, each exercise's checks
    only, each in its own results file and log."""
    made = []

    def make():
        made.append(FakeContext())
        return made[-1]

    commands = [serve_command(tmp_path, "move_server.py", 1), serve_command(tmp_path, "approach_server.py", 2)]
    runner.serve(SUITE, make, iter(commands), log=lambda line: None)
    assert len(made) == 1 and made[0].stopped == 2
    first = json.loads((tmp_path / "checks-1.json").read_text())
    assert [check["id"] for check in first["checks"]] == ["move_true", "move_false"] and first["score"] == 22
    assert set(first["services"]) == {"/move_service"}
    second = json.loads((tmp_path / "checks-2.json").read_text())
    assert len(second["checks"]) == 8 and {check["verdict"] for check in second["checks"]} == {ERROR}
    first_log = (tmp_path / "checks-1.log").read_text().splitlines()
    assert first_log[1].endswith("s to find them") and first_log[2].startswith("[1/2] pass")
    assert re.fullmatch(r"\d+\.\d s: judge \d+\.\d\d", first_log[3].strip())   # where the check's time went
    assert (tmp_path / "checks-2.log").read_text().splitlines()[-1].startswith("score 0/34 ->")


def test_serve_stops_after_an_interrupted_exercise_and_errors_a_context_that_cannot_start(tmp_path):
    commands = [serve_command(tmp_path, "move_server.py", 1), serve_command(tmp_path, "timed_move_server.py", 2)]
    runner.serve(SUITE, lambda: FakeContext(interrupt_at=2), iter(commands), log=lambda line: None)
    assert json.loads((tmp_path / "checks-1.json").read_text())["complete"] is False
    assert not (tmp_path / "checks-2.json").exists()

    def broken():
        raise CheckError("no ground-truth sample after 30 s")
    said = []
    runner.serve(SUITE, broken, iter(commands[1:]), log=said.append)
    assert said == ["setup failed: CheckError: no ground-truth sample after 30 s"]
    document = json.loads((tmp_path / "checks-2.json").read_text())
    assert document["checks"][0]["reason"] == "not run: CheckError: no ground-truth sample after 30 s"


@pytest.mark.parametrize("line, named", [
    ("move_server.py", "not a command"),
    ('{"exercise": "move_server.py"}', "KeyError: 'out'"),
    ('{"exercise": "mover.py", "out": "r.json", "log": "r.log"}', "no exercise is served by a file named mover.py"),
])
def test_serve_ends_at_a_bad_command_naming_it(line, named):
    with pytest.raises(SuiteError, match=named):
        runner.serve(SUITE, FakeContext, iter([line]), log=lambda text: None)


def test_main_writes_nothing_for_a_bad_suite(tmp_path, capsys):
    out = tmp_path / "r.json"
    assert runner.main(["--suite", "week9", "--out", str(out)]) == 2
    assert "no suite named 'week9'" in capsys.readouterr().err
    assert not out.exists()


# ---- interference ----------------------------------------------------------------------------------------------------

def test_interference_outranks_a_perfect_looking_motion_and_names_what_was_done():
    """A submission that forged its own /odom and paused physics gets "interference", never "pass", whatever the
    recording shows; the reason and the evidence name what it did."""
    seen = Seen(samples=(), changes=(WorldChange(101.0, "pause_physics", ""),
                                     WorldChange(106.0, "set_model_state", "turtlebot3_waffle")), paused_at=(101.0,))
    words = interference.findings(seen, {"/odom": {"/fake_move_server"}, "/clock": {"/fake_move_server"}}, False,
                                  "/gazebo")
    observation = observe([(5.0, 0.1, 0), (1.0, 0, 0)], {"response_signal": True, "response_message": "done"})
    verdict = judge("move_true", observation._replace(interference=tuple(words)))
    assert verdict.verdict == INTERFERENCE
    for part in ("physics was paused (from 101.00 s", "called /gazebo/pause_physics at 101.00 s",
                 "called /gazebo/set_model_state (turtlebot3_waffle)", "published /clock (node /fake_move_server)",
                 "published /odom (node /fake_move_server)"):
        assert part in verdict.reason, verdict.reason
    assert verdict.evidence["interference"] == words
    assert score([CheckResult("move_true", "", 16, verdict)]) == (0, 16)


def test_only_other_nodes_publishing_the_simulators_topics_count():
    publishers = [("/clock", ["/gazebo"]), ("/odom", ["/gazebo", "/student"]), ("/cmd_vel", ["/student"]),
                  ("/tf", ["/gazebo"]), ("/rosout", ["/student"])]
    assert interference.foreign_publishers(publishers, "/gazebo") == {"/odom": {"/student"}}
    assert interference.findings(Seen((), (), ()), {}, True, "/gazebo") == [
        "registered a node under the simulator's name /gazebo"]
    assert interference.findings(Seen((), (), ()), {}, False, "/gazebo") == []


def test_a_check_whose_preparation_meets_paused_physics_gets_interference():
    class PausedContext(FakeContext):
        def prepare(self, still_timeout_s):
            raise InterferenceError(["physics was paused (from 3.00 s of sim time)"])

    found = FakeContext().find_services(SUITE.services, 0)
    verdict = service_checks.run_check(CHECKS["move_true"], SUITE, PausedContext(), found["/move_service"])
    assert verdict.verdict == INTERFERENCE and "physics was paused" in verdict.reason
