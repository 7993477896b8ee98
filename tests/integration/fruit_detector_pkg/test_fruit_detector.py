"""fruit_detector_pkg against tb3_sim's camera (roslaunch tb3_sim tb3_sim.launch world:=fruit_world at 640x480,
then roslaunch fruit_detector_pkg detect_fruit_launch_file.launch): the apple (ahead, left) and the banana
(ahead, right) are reported in view where they are; an apple moved away with /gazebo/set_model_state is not;
unknown words are refused; each answer publishes the annotated frame on /image_detected_fruit."""
import numpy as np
import pytest
import rospy
from custom_interfaces.srv import StringServiceMessage
from gazebo_msgs.msg import ModelState
from gazebo_msgs.srv import SetModelState
from geometry_msgs.msg import Point, Pose, Quaternion

from roslab import wait_for_param, wait_for_service, wait_until

WIDTH, HEIGHT = 640, 480
APPLE_HOME = (1.0, 0.25)
OUT_OF_VIEW = (-1.5, 0.0)      # behind the robot, inside the 4 x 4 m room
ANNOTATED = "/image_detected_fruit"
BOX_GREEN = (0, 255, 0)


def detect(word):
    return rospy.ServiceProxy("/detect_fruit_service", StringServiceMessage)(word)


@pytest.fixture(scope="module")
def detector(ros_master):
    ros_master.roslaunch("tb3_sim", "tb3_sim.launch", "world:=fruit_world", "gui:=false",
                         "camera_width:={}".format(WIDTH), "camera_height:={}".format(HEIGHT))
    wait_for_param(ros_master.uri, "/use_sim_time")
    ros_master.roslaunch("fruit_detector_pkg", "detect_fruit_launch_file.launch")
    wait_for_service(ros_master.uri, "/detect_fruit_service", timeout_s=60)
    wait_for_service(ros_master.uri, "/gazebo/set_model_state", timeout_s=60)
    wait_until(lambda: "no camera image" not in detect("apple").message, 30, "the first camera image")
    probe = ros_master.probe()
    probe.subscribe(ANNOTATED, "sensor_msgs/Image")
    return probe


def wait_for_answer(word, success, timeout_s=10):
    """The first reply to `word` whose success is `success` (the camera shows a change within a frame or two)."""
    def answered():
        reply = detect(word)
        return reply if reply.success is success else None
    return wait_until(answered, timeout_s, "success {} for {!r}".format(success, word))


def move_apple(x, y):
    state = ModelState(model_name="apple", pose=Pose(Point(x, y, 0.0), Quaternion(0, 0, 0, 1)),
                       reference_frame="world")
    assert rospy.ServiceProxy("/gazebo/set_model_state", SetModelState)(model_state=state).success


def coordinates(message):
    """(x, y) in pixels from an "... detected at x=..., y=... (...)" message."""
    x_text, y_text = message.split(" detected at ")[1].split(" (")[0].split(", ")
    return float(x_text[2:]), float(y_text[2:])


def test_the_apple_is_in_view_on_the_left(detector):
    reply = detect("apple")
    assert reply.success is True, reply.message
    assert reply.message.startswith("apple detected at x=") and reply.message.endswith("in view")
    assert "left of the centre of the 640x480 image" in reply.message
    x, y = coordinates(reply.message)
    assert 0 < x < WIDTH / 2 and HEIGHT / 2 < y < HEIGHT   # left, and below the horizon: it stands on the floor


def test_the_banana_is_in_view_on_the_right(detector):
    reply = detect("banana")
    assert reply.success is True, reply.message
    assert "right of the centre" in reply.message
    assert WIDTH / 2 < coordinates(reply.message)[0] < WIDTH


def test_words_are_matched_ignoring_case_and_spaces(detector):
    assert detect("  APPLE ").success is True
    assert detect("Banana\n").success is True


@pytest.mark.parametrize("word", ["kiwi", "", "apples", "red apple"])
def test_unknown_words_are_refused(detector, word):
    reply = detect(word)
    assert (reply.success, reply.message) == (False, "unknown fruit '{}': detect must be apple or banana".format(word))


def test_an_apple_moved_out_of_view_is_not_seen(detector):
    try:
        move_apple(*OUT_OF_VIEW)
        assert wait_for_answer("apple", False).message == "no apple in view"
        assert detect("banana").success is True
    finally:
        move_apple(*APPLE_HOME)
    wait_for_answer("apple", True)


def test_each_answer_publishes_the_annotated_frame(detector):
    detector.take(ANNOTATED)
    detect("apple")
    image = detector.wait_for_message(ANNOTATED, timeout_s=10)
    assert (image["width"], image["height"], image["encoding"]) == (WIDTH, HEIGHT, "bgr8")
    assert image["header"]["frame_id"] == "camera_rgb_optical_frame"
    pixels = np.array(image["data"], np.uint8).reshape(HEIGHT, image["step"] // 3, 3)[:, :WIDTH]
    green = (pixels == BOX_GREEN).all(axis=2)
    assert green[:, :WIDTH // 2].sum() > 50, "the apple's box is drawn on the left half"
    detect("kiwi")
    assert detector.collect(ANNOTATED, 0.5) == [], "a refused request publishes nothing"
