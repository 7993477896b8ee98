"""Calibration, Part 5 (suites/part5.yaml): the lab's week5_actions (CameraSweep and Search) scores full marks,
measured from the simulator's ground truth, and a package whose sweep saves files that are not images and whose
Search server sends no feedback and drives on after its result fails those three checks only; both graded in one
run."""
import json

import pytest

from .grading import GRADE_TIMEOUT_S, by_id, grade_class, others_pass, verdicts

pytestmark = pytest.mark.timeout(GRADE_TIMEOUT_S + 60)
CLASS = ("part5_reference", "part5_careless")


@pytest.fixture(scope="module")
def graded(grader_env, tmp_path_factory):
    return grade_class(grader_env, CLASS, tmp_path_factory.mktemp("part5"), "part5").results


@pytest.mark.slow
def test_part5_the_references_score_full_marks_measured_from_ground_truth(graded):
    result = graded["part5_reference"]
    assert set(verdicts(result).values()) == {"pass"}, json.dumps(result["checks"], indent=1)[:3000]
    assert result["score"] == result["max_score"] == 100
    checks = by_id(result)
    assert 85 < checks["sweep_90_4"]["evidence"]["motion"]["turn_deg"] < 95
    assert [fields["current_image"] for _, fields in checks["sweep_90_4"]["evidence"]["feedback"]] == [1, 2, 3, 4]
    assert checks["sweep_90_4"]["evidence"]["images"]["decodable"] == 4
    assert abs(checks["search_stops_at_distance"]["evidence"]["front_distance_m"] - 0.4) < 0.03
    assert abs(checks["search_stops_at_distance"]["evidence"]["motion"]["mean_speed_mps"] - 0.1) < 0.01
    assert {node["exercise"]: node["found_by"] for node in result["nodes"]} == dict.fromkeys(
        ("action_server.py", "search_server.py"), "the course's file name")


@pytest.mark.slow
def test_part5_unreadable_images_no_feedback_and_driving_on_fail_those_checks(graded):
    result = graded["part5_careless"]
    checks = by_id(result)
    sweep = checks["sweep_90_4"]
    assert sweep["verdict"] == "fail", sweep
    assert sweep["reason"].endswith("it holds 4 image files, 0 of them decodable"), sweep["reason"]
    stops = checks["search_stops_at_distance"]
    assert stops["verdict"] == "fail", stops
    assert "expected the robot to be still" in stops["reason"] and "it was moving" in stops["reason"], stops["reason"]
    assert stops["evidence"]["motion"]["end_v"] > 0.05
    feedback = checks["search_feedback_and_result"]
    assert feedback["verdict"] == "fail", feedback
    assert "expected at least 3 feedback messages, it sent 0" in feedback["reason"], feedback["reason"]
    others_pass(result, "sweep_90_4", "search_stops_at_distance", "search_feedback_and_result")
    assert result["score"] == 35
