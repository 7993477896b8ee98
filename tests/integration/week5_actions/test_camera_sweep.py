"""The Week 5 action servers against tb3_sim in colour_search at 2x real time, on one master and simulator.

CameraSweep (roslaunch week5_actions camera_sweep.launch): a 90 degree sweep saves 4 decodable JPEGs while the
robot turns 90 degrees (measured on /odom); refused goals abort at once without motion or files; a cancel preempts
the goal, keeps the images so far and stops the robot within 1 s of sim time; the course's client prints feedback
and the result, and Ctrl-C in the client cancels its goal.
Search (roslaunch week5_actions search.launch), towards the red pillar 1.2 m ahead: it stops 0.4 m from it with
feedback of the distance travelled and the result's fields matching the motion; refused goals abort without
motion; a cancel preempts the goal and stops the robot within 1 s of sim time."""
import math
import re
import signal
import subprocess
import time

import cv2
import pytest
import rospy
from actionlib_msgs.msg import GoalStatus
from std_srvs.srv import Empty

from roslab import wait_until
from roslab.robot_view import angle_between, pose_of

TURN_TOLERANCE_DEG = 5.0
STILL_M = 0.005
STOP_WITHIN_SIM_S = 1.0


@pytest.fixture(autouse=True)
def start_still_at_spawn(sweeper):
    """Every test starts with the robot back at the origin facing +x (the red pillar), and still."""
    rospy.ServiceProxy("/gazebo/reset_world", Empty)()
    sweeper.probe.take("/odom")
    sweeper.probe.wait_for_message("/odom", predicate=lambda odom: abs(pose_of(odom)[2]) < 0.01
                                   and sweeper.is_still(odom))


def image_names(folder):
    return sorted(path.name for path in folder.iterdir())


def test_a_90_degree_sweep_saves_4_images_while_turning_90_degrees(sweeper):
    before = sweeper.view.settled_pose()
    goal = sweeper.send(90.0, 4)
    result = sweeper.result(goal)
    after = sweeper.view.settled_pose()
    assert result["status"]["status"] == GoalStatus.SUCCEEDED, result
    assert sweeper.turned_deg(before, after) == pytest.approx(90.0, abs=TURN_TOLERANCE_DEG)
    assert math.hypot(after[0] - before[0], after[1] - before[1]) < STILL_M
    folder = sweeper.folder(result["result"]["image_path"])
    assert re.fullmatch(r"\d{8}_\d{6}(_\d+)?", folder.name), folder.name
    assert image_names(folder) == ["img001.jpg", "img002.jpg", "img003.jpg", "img004.jpg"]
    images = [cv2.imread(str(folder / name)) for name in image_names(folder)]
    assert all(image is not None and image.shape == (sweeper.height, sweeper.width, 3) for image in images)
    assert len({image.tobytes() for image in images}) == 4, "each image shows a different view"
    feedback = sweeper.feedback(goal)
    assert [image for image, _ in feedback] == [1, 2, 3, 4]
    for (_, angle), target in zip(feedback, (22.5, 45.0, 67.5, 90.0)):
        assert target <= angle < target + 3.0, feedback


@pytest.mark.parametrize("sweep_angle, image_count, reason", [
    (90.0, 0, "image_count 0 is not in 1..50: there must be at least one image"),
    (90.0, 51, "image_count 51 is not in 1..50: that is too many images, the maximum is 50"),
    (90.0, -4, "image_count -4 is not in 1..50"),
    (-90.0, 4, "sweep_angle -90 degrees is not in (0, 180]"),
    (0.0, 4, "sweep_angle 0 degrees is not in (0, 180]"),
    (270.0, 4, "sweep_angle 270 degrees is not in (0, 180]"),
])
def test_invalid_goals_are_aborted_without_motion_or_files(sweeper, sweep_angle, image_count, reason):
    before = sweeper.view.settled_pose()
    folders = sweeper.saved_folders()
    started = time.monotonic()
    result = sweeper.result(sweeper.send(sweep_angle, image_count), timeout_s=10)
    assert time.monotonic() - started < 2.0
    assert result["status"]["status"] == GoalStatus.ABORTED
    assert result["result"]["image_path"].startswith("None [ABORTED: " + reason)
    assert result["status"]["text"] == result["result"]["image_path"]
    time.sleep(0.5)
    after = sweeper.view.settled_pose()
    assert math.hypot(after[0] - before[0], after[1] - before[1]) < 0.002
    assert abs(angle_between(before[2], after[2])) < 0.002
    assert sweeper.saved_folders() == folders


def test_a_cancelled_sweep_is_preempted_keeps_its_images_and_stops_the_robot(sweeper):
    before = sweeper.view.settled_pose()
    goal = sweeper.send(180.0, 10)
    sweeper.wait_for_feedback(goal, 2)
    sweeper.cancel(goal)
    result = sweeper.result(goal, timeout_s=10)
    assert result["status"]["status"] == GoalStatus.PREEMPTED, result
    captured = int(re.search(r"\[PRE-EMPTED at image (\d+) of 10\]$", result["result"]["image_path"]).group(1))
    assert 2 <= captured < 10
    folder = sweeper.folder(result["result"]["image_path"])
    assert image_names(folder) == ["img{:03d}.jpg".format(n) for n in range(1, captured + 1)]
    odom = sweeper.odom_after(result["header"]["stamp"] + STOP_WITHIN_SIM_S)
    assert sweeper.is_still(odom), odom["twist"]
    after = sweeper.view.settled_pose()
    assert sweeper.turned_deg(before, after) < 18.0 * (captured + 1), "the robot stopped at the cancel"


@pytest.mark.realtime   # the client's feedback subscriber must be connected when the first feedback goes out
def test_the_course_client_prints_feedback_and_the_result(ros_master, sweeper):
    run = subprocess.run(["rosrun", "week5_actions", "action_client.py"], env=ros_master.env,
                         stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, timeout=60)
    assert run.returncode == 0, run.stdout
    feedback = re.findall(r"FEEDBACK: current angle ([\d.]+) degrees, image\(s\) captured so far: (\d)", run.stdout)
    assert [int(image) for _, image in feedback] == [1, 2, 3, 4], run.stdout
    path = re.search(r"RESULT: state SUCCEEDED, image_path: (\S+)", run.stdout).group(1)
    assert len(image_names(sweeper.folder(path))) == 4


def test_ctrl_c_in_the_client_cancels_its_goal(ros_master, sweeper):
    sweeper.probe.take("/camera_sweep_action_server/result")
    client = ros_master.rosrun("week5_actions", "action_client.py")
    wait_until(lambda: "image(s) captured so far: 1" in client.output(), 30, "the client's first feedback")
    client.signal(signal.SIGINT)
    assert client.popen.wait(timeout=20) == 1
    result = sweeper.probe.wait_for_message(
        "/camera_sweep_action_server/result", 10, lambda msg: msg["status"]["status"] == GoalStatus.PREEMPTED)
    assert sweeper.is_still(sweeper.odom_after(result["header"]["stamp"] + STOP_WITHIN_SIM_S))


SEARCH_STOP_TOLERANCE_M = 0.03


def test_a_search_stops_at_the_approach_distance_with_feedback_and_result(sweeper, searcher):
    before = sweeper.view.settled_pose()
    goal = searcher.send(fwd_velocity=0.1, approach_distance=0.4)
    result = searcher.result(goal)
    after = sweeper.view.settled_pose()
    assert result["status"]["status"] == GoalStatus.SUCCEEDED, result["status"]["text"]
    assert result["status"]["text"].startswith("Stopped 0.40 m from the object ahead"), result
    fields = result["result"]
    travelled = math.hypot(after[0] - before[0], after[1] - before[1])
    assert fields["total_distance_travelled"] == pytest.approx(travelled, abs=0.01)
    assert after[0] - before[0] == pytest.approx(travelled, abs=0.005), "straight ahead"
    assert fields["closest_object_distance"] == pytest.approx(0.4, abs=SEARCH_STOP_TOLERANCE_M)
    assert abs(fields["closest_object_angle"]) <= 20.0
    distances = [feedback["current_distance_travelled"] for feedback in searcher.feedback(goal)]
    assert len(distances) >= 5, distances      # one per LiDAR sweep (5 Hz) over ~7 s of driving
    assert distances == sorted(distances) and distances[0] < 0.05, distances
    assert distances[-1] == pytest.approx(fields["total_distance_travelled"], abs=1e-6)


@pytest.mark.parametrize("goal, reason", [
    ({"fwd_velocity": 0.3, "approach_distance": 0.4}, "fwd_velocity 0.3 m/s is not in (0, 0.26]"),
    ({"fwd_velocity": 0.1, "approach_distance": -0.4}, "approach_distance -0.4 m is not in [0.2, 3.5)"),
])
def test_invalid_search_goals_are_aborted_without_motion(sweeper, searcher, goal, reason):
    before = sweeper.view.settled_pose()
    started = time.monotonic()
    result = searcher.result(searcher.send(**goal), timeout_s=10)
    assert time.monotonic() - started < 2.0
    assert result["status"]["status"] == GoalStatus.ABORTED
    assert result["status"]["text"].startswith("Goal refused: " + reason), result
    time.sleep(0.5)
    after = sweeper.view.settled_pose()
    assert math.hypot(after[0] - before[0], after[1] - before[1]) < 0.002


def test_a_cancelled_search_is_preempted_and_stops_the_robot(sweeper, searcher):
    goal = searcher.send(fwd_velocity=0.1, approach_distance=0.2)    # ~0.9 m to drive: 9 s, cancelled after 1
    searcher.wait_for_feedback(goal, lambda fields: fields["current_distance_travelled"] >= 0.1)
    searcher.cancel(goal)
    result = searcher.result(goal, timeout_s=10)
    assert result["status"]["status"] == GoalStatus.PREEMPTED, result["status"]["text"]
    travelled = result["result"]["total_distance_travelled"]
    assert travelled >= 0.1, result
    assert result["status"]["text"] == "Cancelled: stopped after {:.3f} m.".format(travelled)
    assert sweeper.is_still(sweeper.odom_after(result["header"]["stamp"] + STOP_WITHIN_SIM_S))
