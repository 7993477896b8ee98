"""week6_vision's colour_search.py and object_detection.py in `roslaunch tuos_simulations coloured_pillars.launch`
(10x real time, a 160x120 camera at 5 frames per sim second):
- colour search, asked for all four pillars, stops facing each in turn: while it reports "SEARCH COMPLETE: The robot
  is now facing the <colour> pillar." the robot stands still with that pillar's centre straight ahead of the camera
  (the camera sits 4.7 cm right of the robot's centre, so the bearing is taken from the camera), then it exits;
- object detection, run with no display and the robot turned toward the blue pillar, writes its four pictures, the
  masked one showing the pillar's blue, and says where the blue object is."""
import math

import cv2
import pytest
import rospy
from gazebo_msgs.msg import ModelState
from gazebo_msgs.srv import SetModelState

from roslab import RosProcess, wait_until
from roslab.launch_args import CHEAP_CAMERA
from roslab.master import node_path
from roslab.robot_view import pose_of

from .conftest import launch_course_world

PILLARS = {"red": (0.6, 0.6), "green": (-0.6, 0.6), "turquoise": (-0.6, -0.6), "blue": (0.6, -0.6)}
CAMERA_IN_BASE_M = (0.069, -0.047)   # camera_rgb_frame in base_footprint (turtlebot3_waffle.urdf.xacro)
FACING_TOLERANCE_DEG = 2.5           # the search stops within 0.8 deg; 1 px of a 160 px image is 0.5 deg
PAUSE_S = 10.0                       # sim seconds facing each pillar: 1 s of wall time to look at the robot


@pytest.fixture(scope="module")
def pillars(ros_master, probe):
    return launch_course_world(ros_master, probe, "coloured_pillars.launch", *CHEAP_CAMERA)


def bearing_error_deg(pose, target):
    """Degrees between the robot's heading and the direction from its camera to `target` (x, y)."""
    x, y, yaw = pose
    camera_x = x + CAMERA_IN_BASE_M[0] * math.cos(yaw) - CAMERA_IN_BASE_M[1] * math.sin(yaw)
    camera_y = y + CAMERA_IN_BASE_M[0] * math.sin(yaw) + CAMERA_IN_BASE_M[1] * math.cos(yaw)
    bearing = math.atan2(target[1] - camera_y, target[0] - camera_x)
    return math.degrees(math.remainder(bearing - yaw, 2 * math.pi))


def test_colour_search_stops_facing_each_pillar_it_looks_for(ros_master, pillars):
    colours = ["red", "green", "turquoise", "blue"]
    pillars.take("/rosout_agg")
    search = ros_master.rosrun("week6_vision", "colour_search.py", "_colours:=" + ",".join(colours),
                               f"_pause:={PAUSE_S}")
    for colour in colours:
        report = f"SEARCH COMPLETE: The robot is now facing the {colour} pillar."
        pillars.wait_for_message("/rosout_agg", timeout_s=90, predicate=lambda log: log["msg"] == report)
        pillars.take("/odom")
        still = pillars.wait_for_message("/odom", predicate=lambda m: abs(m["twist"]["twist"]["angular"]["z"]) < 1e-3)
        assert abs(bearing_error_deg(pose_of(still), PILLARS[colour])) < FACING_TOLERANCE_DEG, colour
    wait_until(lambda: not search.running(), 60, "colour_search.py to exit after the last colour")


def test_object_detection_writes_its_pictures_with_no_display(ros_master, pillars, tmp_path):
    face_blue = ModelState(model_name="turtlebot3_waffle")
    face_blue.pose.orientation.z, face_blue.pose.orientation.w = math.sin(-math.pi / 8), math.cos(-math.pi / 8)
    assert rospy.ServiceProxy("/gazebo/set_model_state", SetModelState)(face_blue).success
    env_without_display = {k: v for k, v in ros_master.env.items() if k != "DISPLAY"}
    detection = RosProcess([node_path("week6_vision", "object_detection.py"), "_colour:=blue",
                            f"_folder:={tmp_path}"], env_without_display, tmp_path / "object_detection.log")
    try:
        wait_until(lambda: not detection.running(), 60, "object_detection.py to save its pictures and exit")
    finally:
        detection.stop()
    names = sorted(p.name for p in tmp_path.glob("step*.jpg"))
    assert names == ["step1_original.jpg", "step2_cropped.jpg", "step3_mask.jpg", "step4_masked.jpg"]
    masked = cv2.imread(str(tmp_path / "step4_masked.jpg"))
    hsv = cv2.cvtColor(masked, cv2.COLOR_BGR2HSV)
    blue = (abs(hsv[..., 0].astype(int) - 120) < 12) & (hsv[..., 1] > 120) & (hsv[..., 2] > 50)
    assert blue.sum() > 0.02 * blue.size, "the masked picture shows the blue pillar"
    assert "The blue object is at x=" in detection.output()
