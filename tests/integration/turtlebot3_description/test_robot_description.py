"""The original launch-file idiom for a TurtleBot3 model on this workspace: robot_description from
`$(find xacro)/xacro --inorder $(find turtlebot3_description)/urdf/turtlebot3_waffle.urdf.xacro` and Debian's
robot_state_publisher. A user's commands see the original frames: `rosparam get /robot_description` is the URDF,
`rosrun tf tf_echo` prints the original offsets, and robot_state_publisher honours `tf_prefix` (the way
multi_turtlebot3.launch names each robot's frames)."""
import subprocess
import xml.etree.ElementTree as ET

import pytest
import yaml

from roslab import RosProcess, wait_for_param, wait_for_topic

XACRO_COMMAND = ("$(find xacro)/xacro --inorder "
                 "$(find turtlebot3_description)/urdf/turtlebot3_{model}.urdf.xacro")
SINGLE_ROBOT_LAUNCH = """<launch>
  <param name="robot_description" command="{command}"/>
  <node pkg="robot_state_publisher" type="robot_state_publisher" name="robot_state_publisher"/>
</launch>
"""
MULTI_ROBOT_LAUNCH = """<launch>
  <group ns="tb3_0">
    <param name="robot_description" command="{command}"/>
    <node pkg="robot_state_publisher" type="robot_state_publisher" name="robot_state_publisher">
      <param name="publish_frequency" type="double" value="50.0"/>
      <param name="tf_prefix" value="tb3_0"/>
    </node>
  </group>
</launch>
"""
# Optical frame: z ahead, x right, y down; rpy (-1.57, 0, -1.57) as a quaternion (x, y, z, w).
OPTICAL_QUATERNION = (-0.5, 0.5, -0.5, 0.5)
IDENTITY_QUATERNION = (0.0, 0.0, 0.0, 1.0)
TF_ECHO_DECIMALS = 0.0011   # tf_echo prints three decimals


def start_launch_file(ros_master, tmp_path, name, text, env):
    path = tmp_path / name
    path.write_text(text)
    return RosProcess(["roslaunch", "--wait", str(path)], env, tmp_path / (name + ".log"))


@pytest.fixture(scope="module")
def waffle(ros_master, tmp_path_factory):
    """The single-robot launch file, run with a PATH whose first python3 cannot run xacro (like a pyenv or conda
    python ahead of the lab's venv): the xacro command must find the lab's interpreter by itself."""
    workdir = tmp_path_factory.mktemp("description")
    foreign_bin = workdir / "foreign-bin"
    foreign_bin.mkdir()
    (foreign_bin / "python3").write_text("#!/bin/sh\necho 'a python3 without ROS or xacro' >&2\nexit 1\n")
    (foreign_bin / "python3").chmod(0o755)
    env = dict(ros_master.env, PATH="{}:{}".format(foreign_bin, ros_master.env["PATH"]))
    launch = start_launch_file(ros_master, workdir, "waffle.launch",
                               SINGLE_ROBOT_LAUNCH.format(command=XACRO_COMMAND.format(model="waffle")), env)
    try:
        wait_for_param(ros_master.uri, "/robot_description", timeout_s=60)
        wait_for_topic(ros_master.uri, "/tf_static", timeout_s=60)
        yield ros_master
    finally:
        launch.stop()


def test_rosparam_get_robot_description_is_the_waffle_urdf(waffle):
    result = subprocess.run(["rosparam", "get", "/robot_description"], env=waffle.env, stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, text=True, timeout=30)
    assert result.returncode == 0, result.stderr
    robot = ET.fromstring(yaml.safe_load(result.stdout))
    assert robot.tag == "robot" and robot.get("name") == "turtlebot3_waffle"
    assert {link.get("name") for link in robot.findall("link")} >= {
        "base_footprint", "base_link", "wheel_left_link", "wheel_right_link", "caster_back_left_link",
        "caster_back_right_link", "imu_link", "base_scan", "camera_link", "camera_rgb_frame",
        "camera_rgb_optical_frame", "camera_depth_frame", "camera_depth_optical_frame"}


def test_tf_echo_camera_rgb_optical_frame(waffle, tf_echo):
    translation, rotation = tf_echo("base_footprint", "camera_rgb_optical_frame")
    assert translation == pytest.approx((0.069, -0.047, 0.117), abs=TF_ECHO_DECIMALS)
    assert rotation == pytest.approx(OPTICAL_QUATERNION, abs=TF_ECHO_DECIMALS)


def test_tf_echo_base_scan(waffle, tf_echo):
    translation, rotation = tf_echo("base_footprint", "base_scan")
    assert translation == pytest.approx((-0.064, 0.0, 0.132), abs=TF_ECHO_DECIMALS)
    assert rotation == pytest.approx(IDENTITY_QUATERNION, abs=TF_ECHO_DECIMALS)


def test_tf_prefix_names_every_frame_of_a_robot(waffle, tf_echo, tmp_path):
    launch = start_launch_file(waffle, tmp_path, "multi.launch",
                               MULTI_ROBOT_LAUNCH.format(command=XACRO_COMMAND.format(model="burger")), waffle.env)
    try:
        wait_for_param(waffle.uri, "/tb3_0/robot_description", timeout_s=60)
        translation, _ = tf_echo("tb3_0/base_footprint", "tb3_0/base_scan")
    finally:
        launch.stop()
    assert translation == pytest.approx((-0.032, 0.0, 0.182), abs=TF_ECHO_DECIMALS)
