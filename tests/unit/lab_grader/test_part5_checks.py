"""The part5 suite and what action checks judge with a world: the shipped suite loads (two actions in
colour_search with a 640x480 camera); the new expectation keys are validated; `judge_action` measures the robot's
true motion and front distance, counts and orders the feedback, ranges the result's numbers, and reports
interference, naming each expectation missed."""
import copy
import math

import pytest
import yaml

from lab_grader.checks.action_checks import EXPECTATION_JUDGES, ActionObservation, judge_action
from lab_grader.checks.image_folder import ImageFolder
from lab_grader.checks.motion import Sample
from lab_grader.checks.verdicts import FAIL, INTERFERENCE, PASS
from lab_grader.suite_file import Range, SuiteError, load_suite

from .test_suite_file import SUITES_DIR

SUITE = load_suite(SUITES_DIR / "part5.yaml")
CHECKS = {check.id: check for check in SUITE.checks}


def test_the_shipped_part5_suite_grades_both_servers_in_colour_search():
    assert SUITE.world == "colour_search" and SUITE.max_score == 100
    assert SUITE.launch_args() == ["camera_width:=640", "camera_height:=480"]
    assert [(a.name, a.type, a.node) for a in SUITE.actions] == [
        ("/camera_sweep_action_server", "tuos_msgs/CameraSweep", "action_server.py"),
        ("/search_action_server", "tuos_msgs/Search", "search_server.py")]
    assert [e.check_ids[0] for e in SUITE.exercises()] == ["sweep_90_4", "search_stops_at_distance"]
    sweep = CHECKS["sweep_90_4"].expect
    assert sweep.feedback == {"current_image": (1, 2, 3, 4)} and sweep.feedback_rising == ("current_angle",)
    assert sweep.motion.turn_deg == Range(80, 100)
    search = CHECKS["search_stops_at_distance"].expect
    assert search.motion.mean_speed_mps == Range(pytest.approx(0.08), pytest.approx(0.12))
    assert search.front_distance_m == Range(pytest.approx(0.35), pytest.approx(0.45))
    assert CHECKS["search_feedback_and_result"].expect.result_ranges["closest_object_angle"] == Range(-20, 20)


def load_changed(tmp_path, change):
    data = copy.deepcopy(yaml.safe_load((SUITES_DIR / "part5.yaml").read_text()))
    change(data)
    path = tmp_path / "changed.yaml"
    path.write_text(yaml.safe_dump(data))
    return load_suite(path)


@pytest.mark.parametrize("change, message", [
    (lambda d: d["checks"][0]["expect"].update(feedback_rising="current_angle"),
     r"checks\[0\]\.expect\.feedback_rising: expected a non-empty list of field names"),
    (lambda d: d["checks"][0]["expect"].update(feedback_count=3), r"feedback_count: expected a mapping"),
    (lambda d: d["checks"][5]["expect"]["result_ranges"].update(closest_object_angle={"mn": 1}),
     r"result_ranges\.closest_object_angle\.mn: unknown key"),
    (lambda d: d["checks"][4]["expect"]["motion"].update(mean_speed_mps=0.1),
     r"motion\.mean_speed_mps: expected a mapping"),
    (lambda d: d.pop("world"), r"simulator_args: needs a world"),
    (lambda d: d["checks"][0]["expect"]["images"].update(count=2.5),
     r"checks\[0\]\.expect\.images\.count: expected a whole number of images, got 2.5"),
    (lambda d: d["checks"][0]["expect"]["images"].pop("path_field"), r"images\.path_field: missing \(required\)"),
    (lambda d: (d.pop("world"), d.pop("simulator_args")), r"checks\[0\]\.expect\.motion: needs a robot"),
])
def test_bad_part5_keys_are_named(tmp_path, change, message):
    with pytest.raises(SuiteError, match=message):
        load_changed(tmp_path, change)


def turning(degrees, seconds=4.0, start_s=10.0):
    """Ground truth of a turn on the spot by `degrees` over `seconds`, then 1 s still."""
    steps = int(seconds * 30)
    rate = math.radians(degrees) / seconds
    moving = [Sample(start_s + i / 30, 0.0, 0.0, rate * i / 30, 0.0, rate) for i in range(steps + 1)]
    still = [Sample(start_s + seconds + i / 30, 0.0, 0.0, math.radians(degrees), 0.0, 0.0) for i in range(1, 31)]
    return tuple(moving + still)


def driving(metres, speed, start_s=10.0, stopped=True):
    seconds = metres / speed
    steps = int(seconds * 30)
    moving = [Sample(start_s + i / 30, speed * i / 30, 0.0, 0.0, speed, 0.0) for i in range(steps + 1)]
    end = [Sample(start_s + seconds + i / 30, metres if stopped else metres + speed * i / 30, 0.0, 0.0,
                  0.0 if stopped else speed, 0.0) for i in range(1, 31)]
    return tuple(moving + end)


def sweep(samples, images=(1, 2, 3, 4), angles=(22.6, 45.1, 67.7, 90.2), state="SUCCEEDED", interference=()):
    feedback = tuple((float(i), {"current_image": image, "current_angle": angle})
                     for i, (image, angle) in enumerate(zip(images, angles)))
    return ActionObservation({"sweep_angle": 90, "image_count": 4}, state, "", {"image_path": "~/myrosdata/x"},
                             feedback, 10.0, None, 14.1, samples=samples, interference=interference)


FOUR = ImageFolder("~/myrosdata/x", ("img001.jpg", "img002.jpg", "img003.jpg", "img004.jpg"),
                   ("img001.jpg", "img002.jpg", "img003.jpg", "img004.jpg"))


def test_a_90_degree_sweep_with_feedback_per_image_passes_with_its_turn():
    verdict = judge_action(CHECKS["sweep_90_4"], sweep(turning(90))._replace(images=FOUR), 1.0)
    assert verdict.verdict == PASS, verdict.reason
    assert "turned counter-clockwise 90.0 deg" in verdict.reason
    assert verdict.evidence["motion"]["turn_deg"] == pytest.approx(90.0, abs=0.01)
    assert verdict.evidence["trajectory"][0] == [0.0, 0.0, 0.0, 0.0]


def test_a_short_sweep_with_missing_and_falling_feedback_names_each_problem():
    verdict = judge_action(CHECKS["sweep_90_4"], sweep(turning(45), images=(1, 2), angles=(22.6, 10.0))._replace(
        images=FOUR), 1.0)
    assert verdict.verdict == FAIL
    assert verdict.reason == ("expected feedback current_image [1, 2, 3, 4], it sent [1, 2]; expected feedback "
                              "current_angle never to decrease, it went 22.6 -> 10.0; expected to turn "
                              "counter-clockwise 80..100 deg, it turned counter-clockwise 45.0 deg")


def test_interference_during_a_goal_is_its_verdict():
    verdict = judge_action(CHECKS["sweep_90_4"], sweep(turning(90), interference=("published /odom",)), 1.0)
    assert verdict.verdict == INTERFERENCE and "published /odom" in verdict.reason


def search(samples, distances, result, front=0.40):
    feedback = tuple((i * 0.2, {"current_distance_travelled": d}) for i, d in enumerate(distances))
    return ActionObservation({"fwd_velocity": 0.1, "approach_distance": 0.4}, "SUCCEEDED", "", result, feedback,
                             10.0, None, 18.8, samples=samples, front_distance_m=front, front_measured=True)


RESULT = {"total_distance_travelled": 0.86, "closest_object_distance": 0.5, "closest_object_angle": 0.0}


def test_a_search_at_the_speed_asked_stopping_at_the_distance_passes():
    verdict = judge_action(CHECKS["search_stops_at_distance"], search(driving(0.86, 0.1), [0.1, 0.5], RESULT), 1.0)
    assert verdict.verdict == PASS, verdict.reason
    assert verdict.evidence["motion"]["mean_speed_mps"] == pytest.approx(0.1, abs=0.002)
    assert verdict.evidence["front_distance_m"] == 0.4


def test_a_search_that_never_stops_fails_on_its_speed_stop_and_front_distance():
    verdict = judge_action(CHECKS["search_stops_at_distance"],
                           search(driving(1.0, 0.2, stopped=False), [0.1], RESULT, front=0.05), 1.0)
    assert verdict.verdict == FAIL
    assert "expected to drive at a mean forward speed of 0.08..0.12 m/s, it drove at +0.2" in verdict.reason
    assert "expected the robot to be still 1 s after the reply, it was moving" in verdict.reason
    assert "expected the front LiDAR to read 0.35..0.45 m once still, it read 0.050 m" in verdict.reason


def test_no_feedback_and_a_result_out_of_range_are_named():
    result = dict(RESULT, total_distance_travelled=0.0, closest_object_angle=45.0)
    verdict = judge_action(CHECKS["search_feedback_and_result"], search(driving(0.76, 0.2), [], result), 1.0)
    assert verdict.verdict == FAIL
    assert verdict.reason == ("expected result total_distance_travelled 0.6..0.95, it was 0.0; expected result "
                              "closest_object_angle -20..20, it was 45.0; expected at least 3 feedback messages, "
                              "it sent 0")


def test_motion_without_ground_truth_is_a_fail_that_says_so():
    verdict = judge_action(CHECKS["sweep_no_images"], sweep(None, images=(), state="ABORTED"), 1.0)
    assert verdict.verdict == FAIL
    assert "no ground truth was recorded during the goal" in verdict.reason


def test_each_expectation_kind_is_one_registered_judge():
    assert [judge.__name__ for judge in EXPECTATION_JUDGES] == [
        "state_problems", "result_problems", "feedback_problems", "timing_problems", "robot_problems",
        "images_problems"]


def with_images(found):
    return sweep(turning(90))._replace(images=found)


def test_the_saved_images_are_counted_and_must_decode():
    check = CHECKS["sweep_90_4"]
    four = ("img001.jpg", "img002.jpg", "img003.jpg", "img004.jpg")
    assert judge_action(check, with_images(ImageFolder("~/x", four, four)), 1.0).verdict == PASS
    broken = judge_action(check, with_images(ImageFolder("~/x", four, four[:3])), 1.0)
    assert broken.verdict == FAIL
    assert broken.reason == ("expected 4 decodable images in the folder result image_path names ('~/x'), it holds "
                             "4 image files, 3 of them decodable")
    assert broken.evidence["images"] == {"folder": "~/x", "files": list(four), "decodable": 3, "problem": None}
    outside = judge_action(check, with_images(ImageFolder("/etc", problem="/etc is outside the student's home "
                                                                          "folder")), 1.0)
    assert outside.reason.endswith("('/etc'): /etc is outside the student's home folder")
    assert "the images were not looked at" in judge_action(check, sweep(turning(90)), 1.0).reason
