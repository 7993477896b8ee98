"""The `xacro` command as ROS 1 users call it (`rosrun xacro xacro ...`, `$(find xacro)/xacro ...`): the PyPI
xacro release behind it, `$(find pkg)` through rospack, the deprecated --inorder accepted, `name:=value` arguments,
the lab's venv found whatever python3 comes first on PATH, and one-line errors with a non-zero exit status."""
import os
import subprocess
from pathlib import Path

import pytest

REPO_ROOT = Path(__file__).resolve().parents[3]
XACRO_PACKAGE = REPO_ROOT / "catkin_ws" / "src" / "compat" / "xacro"
WAFFLE_XACRO = REPO_ROOT / "catkin_ws" / "src" / "compat" / "turtlebot3_description" / "urdf" / \
    "turtlebot3_waffle.urdf.xacro"
XACRO_NS = 'xmlns:xacro="http://ros.org/wiki/xacro"'


def run(command, cwd=None, env=None, timeout=60):
    return subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, cwd=cwd, env=env,
                          timeout=timeout)


def rospack_find(package):
    return run(["rospack", "find", package]).stdout.strip()


def write(path, text):
    path.write_text(text)
    return path


def assert_fails_with_one_line(result, message):
    assert result.returncode != 0
    assert result.stdout == ""
    assert "Traceback" not in result.stderr
    first = result.stderr.splitlines()[0]
    assert message in first, result.stderr


def test_find_xacro_is_the_workspace_package_with_its_executable():
    assert Path(rospack_find("xacro")) == XACRO_PACKAGE
    result = run([rospack_find("xacro") + "/xacro", "--inorder", str(WAFFLE_XACRO)])
    assert result.returncode == 0, result.stderr
    assert '<robot name="turtlebot3_waffle">' in result.stdout


def test_rosrun_xacro_xacro_accepts_the_deprecated_inorder_option():
    result = run(["rosrun", "xacro", "xacro", "--inorder", str(WAFFLE_XACRO)])
    assert result.returncode == 0, result.stderr
    assert '<link name="camera_rgb_optical_frame"/>' in result.stdout
    assert "Traceback" not in result.stderr


def test_find_resolves_through_rospack_and_arguments_are_substituted(tmp_path):
    source = write(tmp_path / "robot.urdf.xacro", f"""<robot name="probe" {XACRO_NS}>
  <xacro:arg name="label" default="unset"/>
  <xacro:include filename="$(find turtlebot3_description)/urdf/common_properties.xacro"/>
  <link name="$(find tf)"/>
  <link name="$(find robot_state_publisher)"/>
  <link name="$(arg label)"/>
</robot>""")
    result = run(["rosrun", "xacro", "xacro", str(source), "label:=given"])
    assert result.returncode == 0, result.stderr
    assert f'<link name="{rospack_find("tf")}"/>' in result.stdout                      # this workspace
    assert '<link name="/usr/share/robot_state_publisher"/>' in result.stdout          # a Debian package
    assert '<link name="given"/>' in result.stdout
    assert '<material name="light_black">' in result.stdout                            # the included file


def test_runs_on_the_lab_venv_whatever_python3_comes_first_on_path(tmp_path):
    """roslaunch runs `$(find xacro)/xacro` with the PATH it inherited; a python3 without xacro may come first."""
    foreign = tmp_path / "bin"
    foreign.mkdir()
    write(foreign / "python3", "#!/bin/sh\necho 'not the lab python' >&2\nexit 1\n").chmod(0o755)
    env = {"PATH": "{}:/usr/bin:/bin".format(foreign), "ROS_PACKAGE_PATH": rospack_find("turtlebot3_description")}
    result = run([str(XACRO_PACKAGE / "xacro"), str(WAFFLE_XACRO)], env=env)
    assert result.returncode == 0, result.stderr
    assert '<robot name="turtlebot3_waffle">' in result.stdout


def test_a_xacro_folder_in_the_current_directory_does_not_hide_the_real_module(tmp_path):
    (tmp_path / "xacro").mkdir()
    (tmp_path / "xacro" / "__init__.py").write_text("raise ImportError('the wrong xacro')\n")
    result = run(["rosrun", "xacro", "xacro", str(WAFFLE_XACRO)], cwd=tmp_path)
    assert result.returncode == 0, result.stderr


def test_missing_file(tmp_path):
    result = run(["rosrun", "xacro", "xacro", str(tmp_path / "nothing.urdf.xacro")])
    assert_fails_with_one_line(result, "No such file or directory: {}".format(tmp_path / "nothing.urdf.xacro"))


def test_unknown_package(tmp_path):
    source = write(tmp_path / "bad.xacro", f'<robot name="r" {XACRO_NS}><link name="$(find no_such_pkg)"/></robot>')
    assert_fails_with_one_line(run(["rosrun", "xacro", "xacro", str(source)]), "package 'no_such_pkg' not found")


@pytest.mark.parametrize("body, message", [
    ("<robot name='r'><link", "XML parsing error"),
    (f"<robot name='r' {XACRO_NS}><link name='${{undefined_property}}'/></robot>", "undefined_property"),
    (f"<robot name='r' {XACRO_NS}><xacro:no_such_macro/></robot>", "no_such_macro"),
    (f"<robot name='r' {XACRO_NS}><link name='$(arg missing)'/></robot>", "missing"),
])
def test_bad_xacro(tmp_path, body, message):
    source = write(tmp_path / "bad.xacro", body)
    assert_fails_with_one_line(run(["rosrun", "xacro", "xacro", str(source)]), message)


def test_no_input_prints_usage():
    result = run(["rosrun", "xacro", "xacro"])
    assert result.returncode != 0
    assert "usage: xacro" in result.stderr.lower() and "Traceback" not in result.stderr


@pytest.mark.parametrize("package, launch_file", [
    ("turtlebot3_gazebo", "turtlebot3_empty_world.launch"),
    ("turtlebot3_gazebo", "multi_turtlebot3.launch"),
    ("turtlebot3_bringup", "turtlebot3_remote.launch"),
    ("turtlebot3_description", "turtlebot3_model.launch"),
])
def test_the_labs_launch_files_print_no_inorder_notice(package, launch_file):
    """xacro prints "in-order processing became default in ROS Melodic" for --inorder, as ROS 1's does; the lab's own
    launch files leave the option out, so a first launch shows only lines that mean something. roslaunch runs the
    robot_description commands while it reads the files (--dump-params: no master needed)."""
    env = dict(os.environ, ROS_MASTER_URI="http://localhost:1")   # nothing listens: parameters are only read
    result = run(["roslaunch", "--dump-params", package, launch_file], env=env)
    assert result.returncode == 0, result.stderr
    assert "robot_description" in result.stdout
    assert "in-order" not in result.stdout + result.stderr, result.stderr
