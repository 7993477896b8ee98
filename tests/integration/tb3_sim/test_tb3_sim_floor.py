"""tb3_sim in a world with a floor layer and two static models (tests/unit/tb3_sim/fixtures/floor_worlds): the
static models are listed by name in /gazebo/model_states and get_world_properties, the camera (and its JPEG) shows
a pink floor line where a pinhole at the URDF's mount sees it, depth reads the floor's distance there, and
/gazebo/scene_primitives carries the floor's primitives for other views. One simulator per module (gui off,
320x240 camera, 5x real time)."""
import json
from pathlib import Path

import numpy as np
import pytest
import rospy
from gazebo_msgs.srv import GetWorldProperties

from roslab import wait_for_service, wait_for_topic, wait_until

WORLD = Path(__file__).parents[2] / "unit" / "tb3_sim" / "fixtures" / "floor_worlds" / "every_marking.yaml"
WIDTH, HEIGHT = 320, 240
SPAWN = (-1.5, 0.5)
# camera_rgb_frame in base_footprint from the URDF chain base_link -> camera_link -> camera_rgb_frame.
CAMERA_MOUNT = (0.010 + 0.064 + 0.005 - 0.010, -0.065 + 0.018, 0.010 + 0.094 + 0.013)
# The pink polyline's leg x = -1.0, y 0..0.8 (5 cm wide), across the view ahead of the robot.
LINE_X, LINE_Y = -1.0, 0.5
IMAGE_TOPICS = {"/camera/rgb/image_raw": "sensor_msgs/Image",
                "/camera/rgb/image_raw/compressed": "sensor_msgs/CompressedImage",
                "/camera/depth/image_raw": "sensor_msgs/Image"}


@pytest.fixture(scope="module")
def sim(ros_master):
    ros_master.roslaunch("tb3_sim", "tb3_sim.launch", f"world:={WORLD}", "gui:=false", f"x_pos:={SPAWN[0]}",
                         f"y_pos:={SPAWN[1]}", f"camera_width:={WIDTH}", f"camera_height:={HEIGHT}",
                         "real_time_factor:=5")
    wait_for_topic(ros_master.uri, "/odom", timeout_s=60)
    wait_for_service(ros_master.uri, "/gazebo/get_world_properties")


@pytest.fixture(scope="module")
def camera(ros_master, sim, tmp_path_factory):
    folder = tmp_path_factory.mktemp("images")
    probe = ros_master.probe()
    files = probe.subscribe_images(IMAGE_TOPICS, folder)
    probe.subscribe("/camera/rgb/camera_info", "sensor_msgs/CameraInfo")
    probe.subscribe("/gazebo/model_states", "gazebo_msgs/ModelStates")
    probe.subscribe("/gazebo/scene_primitives", "std_msgs/String")
    wait_until(lambda: all(probe.latest_image(path) is not None for path in files.values()), 60,
               "the first decoded images (the floor texture is built at the first one)")
    return probe, files


def test_static_models_are_listed_by_name(ros_master, camera):
    probe, _ = camera
    names = ["navigation", "arena_walls", "turtlebot3_waffle"]   # no ground_plane: the floor model is the ground
    assert probe.wait_for_message("/gazebo/model_states")["name"] == names
    rospy.init_node("floor_world_test", anonymous=True, disable_signals=True)
    properties = rospy.ServiceProxy("/gazebo/get_world_properties", GetWorldProperties)()
    assert list(properties.model_names) == names


def line_pixel(info):
    """Column and row where the pink line's centre (LINE_X, LINE_Y) is seen, and its depth."""
    fx, cx, fy, cy = info["K"][0], info["K"][2], info["K"][4], info["K"][5]
    depth = LINE_X - SPAWN[0] - CAMERA_MOUNT[0]
    left = LINE_Y - SPAWN[1] - CAMERA_MOUNT[1]
    return round(cx - fx * left / depth), round(cy + fy * CAMERA_MOUNT[2] / depth), depth


def test_the_camera_sees_the_floor_line_where_the_projection_says(camera):
    probe, files = camera
    u, v, depth = line_pixel(probe.wait_for_message("/camera/rgb/camera_info"))
    rgb = probe.latest_image(files["/camera/rgb/image_raw"])
    assert tuple(int(c) for c in rgb[v, u]) == (228, 0, 228), "the line, lit as Gazebo lights the floors"
    assert tuple(int(c) for c in rgb[v - 15, u]) == (228, 228, 228), "the white floor beyond it"
    blue, green, red = (int(c) for c in probe.latest_image(files["/camera/rgb/image_raw/compressed"])[v, u])
    assert red > 180 and blue > 180 and green < 60, f"decoded JPEG pixel ({u}, {v}) is {(red, green, blue)} (RGB)"
    depth_image = probe.latest_image(files["/camera/depth/image_raw"])
    assert depth_image[v, u] == pytest.approx(depth, abs=0.01)
    assert np.isnan(depth_image[0, u]), "no depth in the sky"


def test_scene_primitives_carry_the_floor_for_other_views(camera):
    probe, _ = camera
    scene = json.loads(probe.wait_for_message("/gazebo/scene_primitives")["data"])
    kinds = {primitive["kind"] for primitive in scene}
    assert kinds == {"FilledPolygon", "Polyline", "Disc", "Text"}
    assert scene[0]["rings"] == [[[-2.5, -2.0], [3.5, -2.0], [3.5, 2.0], [-2.5, 2.0]]]
    assert any(p["kind"] == "Text" and p["text"] == "A" for p in scene)
