"""The beginner_tutorials suite and action checks: the shipped suite loads (a service and an action, no world);
action check keys are validated like service ones; `judge_action` turns what happened to a goal into a verdict
whose reason names each expectation missed; a run dispatches action checks to the context's observe_action."""
import copy

import pytest
import yaml

from lab_grader.checks import runner
from lab_grader.checks.action_checks import ActionObservation, judge_action
from lab_grader.checks.motion import Observation
from lab_grader.checks.service_checks import judge
from lab_grader.checks.timeline import Timeline
from lab_grader.checks.verdicts import ERROR, FAIL, PASS, FoundService
from lab_grader.suite_file import Range, SuiteError, load_suite

from .test_suite_file import SUITES_DIR

SUITE = load_suite(SUITES_DIR / "beginner_tutorials.yaml")
CHECKS = {check.id: check for check in SUITE.checks}


def test_the_shipped_beginner_suite_has_a_service_an_action_and_no_world():
    assert SUITE.world is None and SUITE.max_score == 100 and len(SUITE.checks) == 10
    assert [s.name for s in SUITE.services] == ["/add_two_int"]
    assert [(a.name, a.type) for a in SUITE.actions] == [("/my_action_server", "beginner_tutorials/counter")]
    assert SUITE.nodes == ("add_two_int_server.py", "counter_server.py")
    assert CHECKS["add_int64_min"].request == {"a": -2 ** 63, "b": 0}
    assert CHECKS["add_overflow_refused"].expect.refused is True
    three = CHECKS["count_three"]
    assert three.action == "/my_action_server" and three.service is None and three.goal == {"num_counts": 3}
    assert three.expect.states == ("SUCCEEDED",) and three.expect.feedback == {"counts_elapsed": (0, 1, 2)}
    assert three.expect.duration_s == Range(2.5, 3.5)
    assert CHECKS["count_cancelled"].cancel_after_s == 2.5
    assert CHECKS["count_zero_ends"].expect.states == ("ABORTED", "REJECTED", "SUCCEEDED")


def load_changed(tmp_path, change):
    data = yaml.safe_load((SUITES_DIR / "beginner_tutorials.yaml").read_text())
    data = copy.deepcopy(data)
    change(data)
    path = tmp_path / "changed.yaml"
    path.write_text(yaml.safe_dump(data))
    return load_suite(path)


@pytest.mark.parametrize("change, message", [
    (lambda d: d["checks"][7].update(action="/counter"), r"checks\[7\]\.action: '/counter' is not one of the "
                                                        r"suite's actions \(/my_action_server\)"),
    (lambda d: d["checks"][7]["expect"].update(state="DONE"), r"checks\[7\]\.expect\.state: 'DONE' is not a goal"),
    (lambda d: d["checks"][7]["expect"].update(feedback={"counts_elapsed": 3}), r"expected a list of values"),
    (lambda d: d["checks"][7].update(request={"a": 1}), r"checks\[7\]\.request: unknown key"),
    (lambda d: d["checks"][0]["expect"].update(motion={"still_at_end": True}), r"needs a robot"),
    (lambda d: d["checks"][5]["expect"].update(reply={"sum": 0}), r"a refused call has no reply"),
    (lambda d: d["actions"][0].update(type="counter"), r"actions\[0\]\.type: 'counter' is not an action type"),
])
def test_bad_action_checks_are_named(tmp_path, change, message):
    with pytest.raises(SuiteError, match=message):
        load_changed(tmp_path, change)


def observed(state="SUCCEEDED", counts=(0, 1, 2), ended_s=13.0, cancelled_s=None, result="Counting complete!",
             error=None):
    feedback = tuple((float(count), {"counts_elapsed": count}) for count in counts)
    return ActionObservation({"num_counts": 3}, state, "", {"result_message": result}, feedback, 10.0, cancelled_s,
                             ended_s, error)


def test_a_goal_counted_as_the_tutorial_does_passes():
    verdict = judge_action(CHECKS["count_three"], observed())
    assert verdict.verdict == PASS, verdict.reason
    assert verdict.reason == ("ended SUCCEEDED after 3.00 s with result_message='Counting complete!'; "
                              "3 feedback messages")
    assert verdict.evidence["feedback"] == [[0.0, {"counts_elapsed": 0}], [1.0, {"counts_elapsed": 1}],
                                            [2.0, {"counts_elapsed": 2}]]


def test_each_missed_expectation_is_named():
    verdict = judge_action(CHECKS["count_three"], observed(state="ABORTED", counts=(1, 2), ended_s=11.0))
    assert verdict.verdict == FAIL
    assert verdict.reason == ("expected the goal to end SUCCEEDED, it ended ABORTED; expected feedback "
                              "counts_elapsed [0, 1, 2], it sent [1, 2]; expected the goal to end 2.5..3.5 s after "
                              "it was sent, it ended after 1.00 s")


def test_a_cancel_must_end_the_goal_soon():
    check = CHECKS["count_cancelled"]
    assert judge_action(check, observed("PREEMPTED", ended_s=13.0, cancelled_s=12.5)).verdict == PASS
    late = judge_action(check, observed("PREEMPTED", ended_s=15.0, cancelled_s=12.5))
    assert "expected the goal to end at most 1.2 s after the cancel, it ended after 2.50 s" in late.reason
    early = judge_action(check, observed("PREEMPTED", ended_s=11.0, cancelled_s=None))
    assert "it ended before the cancel was sent" in early.reason


def test_no_result_in_time_is_an_error_with_the_feedback_as_evidence():
    verdict = judge_action(CHECKS["count_three"], observed(state=None, ended_s=None, error="no result within 10 s"))
    assert verdict.verdict == ERROR and verdict.reason == "no result within 10 s"
    assert len(verdict.evidence["feedback"]) == 3


def test_a_refused_call_passes_only_when_the_server_answered_with_an_error():
    check = CHECKS["add_overflow_refused"]
    refused = Observation({}, None, "the call failed: ServiceException: service [/add_two_int] responded with an "
                          "error: b'out of range'", 1.0, None, None, server_error=True)
    assert judge(check, refused, 0).verdict == PASS
    wrapped = Observation({}, {"sum": -2 ** 63}, None, 1.0, 1.1, None)
    verdict = judge(check, wrapped, 0)
    assert verdict.verdict == FAIL and "expected the call to be refused" in verdict.reason
    timed_out = Observation({}, None, "no reply within 5 s of sim time", 1.0, None, None)
    assert judge(check, timed_out, 0).verdict == ERROR


def test_int64_sums_compare_exactly():
    check = CHECKS["add_int64_max"]
    close = Observation({}, {"sum": 2 ** 63 - 2}, None, 1.0, 1.1, None)
    assert judge(check, close, 0).verdict == FAIL


class ActionContext:
    """No robot; the service is found, the action is not."""

    def __init__(self):
        self.timeline = Timeline()

    def wait_until_ready(self):
        pass

    def now(self):
        return 0.0

    def find_services(self, specs, grace):
        return {spec.name: FoundService(spec.name, spec.type, spec.name, "by name", spec.type, None) for spec in specs}

    def find_actions(self, specs, grace):
        return {spec.name: FoundService(spec.name, spec.type, None, None, None, "no action") for spec in specs}

    def prepare(self, still_timeout_s):
        pass

    def observe(self, service, request, timeout_s, settle_s, measure_front=False):
        return Observation(request, {"sum": request["a"] + request["b"]}, None, 0.0, 0.1, None)

    def stop_robot(self):
        pass


def test_a_run_dispatches_service_and_action_checks():
    document = runner.run_suite(SUITE, ActionContext, log=lambda line: None)
    verdicts = {check["id"]: (check["verdict"], check["reason"]) for check in document["checks"]}
    assert verdicts["add_small"][0] == PASS and verdicts["add_int64_extremes"][0] == PASS
    assert verdicts["add_overflow_refused"][0] == FAIL     # this context wraps nothing but refuses nothing either
    assert verdicts["count_three"] == (ERROR, "action /my_action_server not found: no action")
    assert document["services"]["/my_action_server"]["found"] is None
    assert document["checks"][7]["evidence"]["goal"] == {"num_counts": 3}
