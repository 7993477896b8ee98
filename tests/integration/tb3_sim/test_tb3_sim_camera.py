"""The Waffle's RealSense camera as course code reads it: Gazebo's topic names, types, encodings and frames, 30 Hz
of sim time, images that cv_bridge decodes, a red box spawned with `spawn_model -sdf` (Gazebo/Red) seen red where
a pinhole camera at the URDF's mount would see it, and image_view showing the stream. One simulator (empty world,
640x480 camera) per module."""
import math
import subprocess

import numpy as np
import pytest

from roslab import wait_for_topic, wait_until
from roslab.graph import subscribers

WIDTH, HEIGHT = 640, 480
# camera_rgb_frame in base_footprint from the URDF chain base_link -> camera_link -> camera_rgb_frame.
CAMERA_MOUNT = (0.010 + 0.064 + 0.005 - 0.010, -0.065 + 0.018, 0.010 + 0.094 + 0.013)
BOX = {"x": 1.5, "y": 0.3, "size": 0.3, "height": 0.4}
RED_BOX_SDF = f"""<?xml version="1.0"?>
<sdf version="1.6"><model name="red_box"><static>true</static><link name="link">
  <collision name="collision"><geometry><box><size>{BOX['size']} {BOX['size']} {BOX['height']}</size></box>
  </geometry></collision>
  <visual name="visual"><geometry><box><size>{BOX['size']} {BOX['size']} {BOX['height']}</size></box></geometry>
    <material><script><uri>file://media/materials/scripts/gazebo.material</uri><name>Gazebo/Red</name></script>
    </material></visual>
</link></model></sdf>
"""
IMAGE_TOPICS = {"/camera/rgb/image_raw": "sensor_msgs/Image",
                "/camera/rgb/image_raw/compressed": "sensor_msgs/CompressedImage",
                "/camera/depth/image_raw": "sensor_msgs/Image"}
INFO_TOPICS = {"/camera/rgb/camera_info": "sensor_msgs/CameraInfo",
               "/camera/depth/camera_info": "sensor_msgs/CameraInfo"}


@pytest.fixture(scope="module")
def sim(ros_master, tmp_path_factory):
    ros_master.roslaunch("tb3_sim", "tb3_sim.launch", "gui:=false", f"camera_width:={WIDTH}",
                         f"camera_height:={HEIGHT}")
    wait_for_topic(ros_master.uri, "/odom")
    sdf = tmp_path_factory.mktemp("models") / "red_box.sdf"
    sdf.write_text(RED_BOX_SDF)
    spawn = subprocess.run(["rosrun", "tb3_sim", "spawn_model", "-sdf", "-file", str(sdf), "-model", "red_box",
                            "-x", str(BOX["x"]), "-y", str(BOX["y"])], env=ros_master.env, capture_output=True,
                           text=True, timeout=60)
    assert spawn.returncode == 0, spawn.stdout + spawn.stderr


@pytest.fixture(scope="module")
def camera(ros_master, sim, tmp_path_factory):
    """A probe on every camera topic (images decoded by cv_bridge into .npy files), started after /use_sim_time."""
    folder = tmp_path_factory.mktemp("images")
    probe = ros_master.probe()
    files = probe.subscribe_images(IMAGE_TOPICS, folder)
    for topic, msg_type in INFO_TOPICS.items():
        probe.subscribe(topic, msg_type)
    probe.subscribe("/tf_static", "tf2_msgs/TFMessage")
    for topic in files:
        probe.wait_for_message(topic)
    wait_until(lambda: all(probe.latest_image(path) is not None for path in files.values()), 20,
               "the first decoded images")
    return probe, files


def test_topic_types_encodings_and_frames(camera):
    probe, _ = camera
    rgb = probe.wait_for_message("/camera/rgb/image_raw")
    depth = probe.wait_for_message("/camera/depth/image_raw")
    compressed = probe.wait_for_message("/camera/rgb/image_raw/compressed")
    info = probe.wait_for_message("/camera/rgb/camera_info")
    assert (rgb["encoding"], rgb["width"], rgb["height"], rgb["step"]) == ("rgb8", WIDTH, HEIGHT, 3 * WIDTH)
    assert (depth["encoding"], depth["width"], depth["height"]) == ("32FC1", WIDTH, HEIGHT)
    assert compressed["format"] == "rgb8; jpeg compressed bgr8"
    assert (info["width"], info["height"], info["distortion_model"]) == (WIDTH, HEIGHT, "plumb_bob")
    assert info["D"] == [0.0] * 5
    focal = WIDTH / (2.0 * math.tan(1.3439 / 2.0))
    assert info["K"] == pytest.approx([focal, 0, (WIDTH + 1) / 2, 0, focal, (HEIGHT + 1) / 2, 0, 0, 1])
    for message in (rgb, depth, compressed, info, probe.wait_for_message("/camera/depth/camera_info")):
        assert message["header"]["frame_id"] == "camera_rgb_optical_frame"


def test_images_come_at_30_hz_of_sim_time(camera):
    """camera_info goes out with every frame (synchronously): its stamps average 1/30 s of sim time apart (30 or
    35 ms on 5 ms physics steps). Images go through a queue that keeps the newest, so a slow subscriber (the probe
    decodes and saves each one) may miss frames, but never gets them faster than that."""
    probe, _ = camera
    probe.take("/camera/rgb/image_raw")
    info = probe.collect("/camera/rgb/camera_info", 1.5)
    assert len(info) >= 15
    assert np.mean(np.diff([entry["msg"]["header"]["stamp"] for entry in info])) == pytest.approx(1.0 / 30.0,
                                                                                                   rel=0.02)
    images = [entry["msg"]["header"]["stamp"] for entry in probe.take("/camera/rgb/image_raw")]
    assert len(images) >= 5
    assert np.diff(images).min() >= 0.030 - 1e-6


def projected_box_pixel(info):
    """Column and row of the red box's near face centre, half-way up, for a level pinhole at the camera mount."""
    fx, cx, fy, cy = info["K"][0], info["K"][2], info["K"][4], info["K"][5]
    depth = BOX["x"] - BOX["size"] / 2.0 - CAMERA_MOUNT[0]
    left = BOX["y"] - CAMERA_MOUNT[1]
    return round(cx - fx * left / depth), round(cy + fy * (CAMERA_MOUNT[2] - BOX["height"] / 2.0) / depth), depth


def test_the_spawned_gazebo_red_box_is_red_where_the_projection_says(camera):
    probe, files = camera
    u, v, depth = projected_box_pixel(probe.wait_for_message("/camera/rgb/camera_info"))
    rgb = probe.latest_image(files["/camera/rgb/image_raw"])
    bgr = probe.latest_image(files["/camera/rgb/image_raw/compressed"])
    assert rgb.shape == (HEIGHT, WIDTH, 3) and bgr.shape == (HEIGHT, WIDTH, 3)
    red, green, blue = (int(c) for c in rgb[v, u])
    assert red > 100 and green < 30 and blue < 30, f"rgb8 pixel ({u}, {v}) is {(red, green, blue)}"
    blue, green, red = (int(c) for c in bgr[v, u])
    assert red > 90 and green < 50 and blue < 50, f"decoded JPEG pixel ({u}, {v}) is {(red, green, blue)} (RGB)"
    edge = u + round(probe.wait_for_message("/camera/rgb/camera_info")["K"][0] * (BOX["size"] / 2 + 0.05) / depth)
    assert not (rgb[v, edge, 0] > 100 and rgb[v, edge, 1] < 30), "the box is no wider than the projection"
    depth_image = probe.latest_image(files["/camera/depth/image_raw"])
    assert depth_image[v, u] == pytest.approx(depth, abs=0.02)
    assert np.isnan(depth_image[0, u]), "no depth in the sky"


def test_static_tf_has_the_optical_frame(camera):
    probe, _ = camera
    static = probe.wait_for_message("/tf_static")
    children = {t["child_frame_id"]: t["header"]["frame_id"] for t in static["transforms"]}
    assert children["camera_rgb_optical_frame"] == "camera_rgb_frame"
    assert children["camera_rgb_frame"] == "camera_link"


def test_image_view_shows_the_stream(ros_master, camera):
    viewer = ros_master.start(["xvfb-run", "-a", "rosrun", "image_view", "image_view",
                               "image:=/camera/rgb/image_raw"], "image_view")
    wait_until(lambda: any("image_view" in node for node in subscribers(ros_master.uri, "/camera/rgb/image_raw")),
               30, "image_view subscribed to /camera/rgb/image_raw")
    probe, _ = camera
    probe.collect("/camera/rgb/image_raw", 2.0)
    assert viewer.running(), "image_view exited:\n" + viewer.output()


def test_by_default_the_launch_file_leaves_the_camera_to_the_model(ros_master):
    """No camera_* parameters unless given, so each robot's camera keeps its model's size and rate (the Waffle's
    R200: 1920x1080 at 30 Hz; see the unit tests of the camera output)."""
    env = {k: v for k, v in ros_master.env.items() if k != "TURTLEBOT3_MODEL"}
    dump = subprocess.run(["roslaunch", "--dump-params", "tb3_sim", "tb3_sim.launch"], env=env,
                          capture_output=True, text=True, timeout=60).stdout
    assert "/gazebo/model: waffle" in dump
    assert "camera_" not in dump
