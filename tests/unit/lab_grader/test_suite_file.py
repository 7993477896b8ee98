"""Suite files: the shipped week4.yaml loads into typed objects; every unknown key and bad value is an error naming
the file and the key path; names resolve to suites/<name>.yaml."""
import copy
import math
from pathlib import Path

import pytest
import yaml

from lab_grader.suite_file import Range, SuiteError, load_suite, resolve_suite

SUITES_DIR = Path(__file__).resolve().parents[3] / "catkin_ws/src/tools/lab_grader/suites"

VALID = {
    "suite": "demo",
    "world": "approach_arena",
    "services": [{"name": "/move_service", "type": "tuos_msgs/SetBool", "node": "move_server.py"}],
    "checks": [{
        "id": "move_true", "title": "moves", "weight": 10, "service": "/move_service",
        "request": {"request_signal": True},
        "expect": {"reply": {"response_signal": True}, "reply_matches": {"response_message": "(?i)done"},
                   "motion": {"forward_m": {"value": 0.5, "tolerance": 0.1}, "turn_deg": {"min": 5},
                              "still_at_end": True},
                   "front_distance_m": {"min": 0.3, "max": 0.5}},
    }],
}


def write(tmp_path, data, name="demo.yaml"):
    path = tmp_path / name
    path.write_text(yaml.safe_dump(data))
    return path


def mutated(change):
    data = copy.deepcopy(VALID)
    change(data)
    return data


def test_the_shipped_week4_suite_loads_with_17_checks_worth_100_points_of_which_7_are_advice():
    suite = load_suite(SUITES_DIR / "week4.yaml")
    assert suite.name == "week4" and suite.world == "approach_arena" and suite.max_score == 100
    assert suite.nodes == ("move_server.py", "timed_move_server.py", "approach_server.py")
    exercises = suite.exercises()
    assert [(exercise.node, [spec.name for spec in exercise.services], len(exercise.check_ids))
            for exercise in exercises] == [("move_server.py", ["/move_service"], 2),
                                           ("timed_move_server.py", ["/timed_move_service"], 7),
                                           ("approach_server.py", ["/approach_service"], 8)]
    assert [service.name for service in suite.services] == ["/move_service", "/timed_move_service",
                                                            "/approach_service"]
    assert len(suite.checks) == 17 and sum(check.weight for check in suite.checks) == 100
    assert len({check.id for check in suite.checks}) == 17
    advice = [check for check in suite.checks if check.kind == "advice"]
    assert len(advice) == 7 and {check.weight for check in advice} == {0}
    assert all(check.id.startswith(("approach_velocity", "approach_distance")) for check in advice)
    move = suite.checks[0]
    assert move.id == "move_true" and move.timeout_s == 15.0 and move.kind == "required"
    # the course template's whole-second timing: a 5 s request moves for 4..5 s (and 0.1 m/s of it)
    assert move.expect.motion.forward_m == Range(0.35, 0.6)
    assert move.expect.motion.duration_s == Range(4.0, 5.5)
    assert "4..5.5 s" in move.title
    timed = next(c for c in suite.checks if c.id == "timed_left")
    assert timed.expect.motion.duration_s == Range(2.0, 3.5) and "2..3.5 s" in timed.title
    nan_check = next(check for check in suite.checks if check.id == "approach_distance_nan")
    assert math.isnan(nan_check.request["approach_distance"])
    assert next(c for c in suite.checks if c.id == "timed_fwd").timeout_s == 10.0    # the suite's default


def test_a_valid_file_loads_into_typed_objects_with_defaults(tmp_path):
    suite = load_suite(write(tmp_path, VALID))
    assert suite.title == "demo" and suite.settle_s == 1.0 and suite.by_type_grace_s == 3.0
    assert suite.services[0].wait_s == 30.0
    assert suite.nodes == ("move_server.py",) and suite.real_time_factor == 1.0 and suite.max_score == 10
    check = suite.checks[0]
    assert check.timeout_s == 30.0
    assert check.expect.motion.forward_m == Range(0.4, 0.6)
    assert check.expect.motion.turn_deg == Range(5.0, None)
    assert check.expect.motion.lateral_max_m is None
    assert check.expect.front_distance_m == Range(0.3, 0.5)
    assert check.expect.reply_matches["response_message"].search("Done.")


def test_a_check_without_expect_accepts_any_reply(tmp_path):
    suite = load_suite(write(tmp_path, mutated(lambda d: d["checks"][0].pop("expect"))))
    expect = suite.checks[0].expect
    assert expect.reply == {} and expect.motion is None and expect.front_distance_m is None


def _set(path, value):
    def change(data):
        *parents, last = path
        target = data
        for key in parents:
            target = target[key]
        target[last] = value
    return change


def _delete(path):
    def change(data):
        *parents, last = path
        target = data
        for key in parents:
            target = target[key]
        del target[last]
    return change


def _duplicate_check(data):
    data["checks"].append(copy.deepcopy(data["checks"][0]))


def _duplicate_service(data):
    data["services"].append(copy.deepcopy(data["services"][0]))


CHECK = ("checks", 0)
MOTION = CHECK + ("expect", "motion")


@pytest.mark.parametrize("change, where, problem", [
    (_set(("colour",), "red"), "colour", "unknown key"),
    (_delete(("suite",)), "suite", "missing"),
    (_set(("suite",), "week 4"), "suite", "not a suite name"),
    (_delete(("world",)), "checks[0].expect.motion", "needs a robot: the suite has no world"),
    (_delete(("services",)), "services", "a suite needs services, actions or runs"),
    (_set(("settle_s",), -1), "settle_s", "must be >= 0"),
    (_set(("timeout_s",), 0), "timeout_s", "must be > 0"),
    (_set(("still_timeout_s",), "ten"), "still_timeout_s", "expected a finite number"),
    (_set(("by_type_grace_s",), True), "by_type_grace_s", "expected a finite number"),
    (_set(("services",), []), "services", "non-empty list"),
    (_set(("services", 0, "name"), "move_service"), "services[0].name", "absolute ROS name"),
    (_set(("services", 0, "type"), "SetBool"), "services[0].type", "service type"),
    (_set(("services", 0, "wait"), 3), "services[0].wait", "unknown key"),
    (_set(("services", 0, "wait_s"), float("nan")), "services[0].wait_s", "finite number"),
    (_duplicate_service, "services[1].name", "listed twice"),
    (_set(("services", 0, "node"), "src/move_server.py"), "services[0].node", "a file name"),
    (_set(("services", 0, "node"), {"executable": "move_server.py"}), "services[0].node", "non-empty string"),
    (_delete(("services", 0, "node")), "services[0].node", "missing"),
    (_set(("real_time_factor",), 0), "real_time_factor", "must be > 0"),
    (_set(("checks",), "all"), "checks", "non-empty list"),
    (_delete(CHECK + ("id",)), "checks[0].id", "missing"),
    (_set(CHECK + ("id",), "Move-True"), "checks[0].id", "check id"),
    (_duplicate_check, "checks[1].id", "used twice"),
    (_delete(CHECK + ("title",)), "checks[0].title", "missing"),
    (_set(CHECK + ("weight",), -2), "checks[0].weight", "must be >= 0"),
    (_delete(CHECK + ("weight",)), "checks[0].weight", "missing"),
    (_set(CHECK + ("kind",), "optional"), "checks[0].kind", "expected one of required, advice"),
    (_set(CHECK + ("wieght",), 2), "checks[0].wieght", "unknown key"),
    (_set(CHECK + ("service",), "/timed_move_service"), "checks[0].service", "not one of the suite's services"),
    (_set(CHECK + ("timeout_s",), -5), "checks[0].timeout_s", "must be > 0"),
    (_set(CHECK + ("request",), ["true"]), "checks[0].request", "mapping of field names"),
    (_set(CHECK + ("request", "request_signal"), [True]), "checks[0].request.request_signal", "bool, number"),
    (_set(CHECK + ("expect", "replies"), {}), "checks[0].expect.replies", "unknown key"),
    (_set(CHECK + ("expect", "reply"), {"response-signal": True}), "checks[0].expect.reply", "not a field name"),
    (_set(CHECK + ("expect", "reply_matches", "response_message"), "(unclosed"),
     "checks[0].expect.reply_matches.response_message", "not a valid regular expression"),
    (_set(MOTION + ("forwards_m",), {"min": 0.1}), "checks[0].expect.motion.forwards_m", "unknown key"),
    (_set(MOTION + ("forward_m",), {"mn": 0.1}), "checks[0].expect.motion.forward_m.mn", "unknown key"),
    (_set(MOTION + ("forward_m",), {"min": "abc"}), "checks[0].expect.motion.forward_m.min", "finite number"),
    (_set(MOTION + ("forward_m",), {"min": 0.6, "max": 0.4}), "checks[0].expect.motion.forward_m",
     "greater than max"),
    (_set(MOTION + ("forward_m",), {"value": 0.5}), "checks[0].expect.motion.forward_m", "either value and"),
    (_set(MOTION + ("forward_m",), {"value": 0.5, "tolerance": 0.1, "min": 0}),
     "checks[0].expect.motion.forward_m", "either value and"),
    (_set(MOTION + ("forward_m",), {}), "checks[0].expect.motion.forward_m", "either value and"),
    (_set(MOTION + ("forward_m",), 0.5), "checks[0].expect.motion.forward_m", "expected a mapping"),
    (_set(MOTION + ("duration_s",), {"value": 5, "tolerance": -1}), "checks[0].expect.motion.duration_s.tolerance",
     "must be >= 0"),
    (_set(MOTION + ("lateral_max_m",), -0.1), "checks[0].expect.motion.lateral_max_m", "must be >= 0"),
    (_set(MOTION + ("still_at_end",), "yes"), "checks[0].expect.motion.still_at_end", "true or false"),
    (_set(CHECK + ("expect", "front_distance_m"), {"value": 0.4, "tolerance": "a bit"}),
     "checks[0].expect.front_distance_m.tolerance", "finite number"),
])
def test_each_bad_key_or_value_is_named_with_the_file(tmp_path, change, where, problem):
    path = write(tmp_path, mutated(change))
    with pytest.raises(SuiteError) as error:
        load_suite(path)
    message = str(error.value)
    assert message.startswith("demo.yaml: {}: ".format(where)), message
    assert problem in message, message


def test_a_file_that_is_not_a_mapping(tmp_path):
    path = tmp_path / "list.yaml"
    path.write_text("- 1\n- 2\n")
    with pytest.raises(SuiteError, match=r"^list\.yaml: \(top level\): expected a mapping"):
        load_suite(path)


def test_broken_yaml_and_missing_files(tmp_path):
    path = tmp_path / "broken.yaml"
    path.write_text("suite: [unclosed\n")
    with pytest.raises(SuiteError, match=r"^broken\.yaml: not valid YAML"):
        load_suite(path)
    with pytest.raises(SuiteError, match="absent.yaml: no such suite file"):
        load_suite(tmp_path / "absent.yaml")


def test_load_suite_takes_a_name_or_a_path(tmp_path):
    assert load_suite("week4").path == SUITES_DIR / "week4.yaml"
    assert load_suite(write(tmp_path, VALID)).name == "demo"
    assert load_suite(str(write(tmp_path, VALID))).name == "demo"


def test_names_resolve_in_the_suites_folder_and_paths_are_paths(tmp_path):
    assert resolve_suite("week4", SUITES_DIR) == SUITES_DIR / "week4.yaml"
    own = write(tmp_path, VALID)
    assert resolve_suite(str(own), SUITES_DIR) == own
    with pytest.raises(SuiteError, match=r"no suite named 'week9' .*known: .*week4"):
        resolve_suite("week9", SUITES_DIR)
    with pytest.raises(SuiteError, match="no such suite file"):
        resolve_suite(str(tmp_path / "nope.yaml"), SUITES_DIR)


def test_an_advice_check_weighs_nothing_unless_given_a_weight(tmp_path):
    data = copy.deepcopy(VALID)
    check = data["checks"][0]
    del check["weight"]
    check["kind"] = "advice"
    suite = load_suite(write(tmp_path, data))
    assert suite.checks[0].kind == "advice" and suite.checks[0].weight == 0 and suite.max_score == 0
