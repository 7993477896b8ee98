"""No display: every launch and tool that would open a window prints one line saying how to see it here (the
browser view, or xvfb-run) and no Qt/wx error or traceback; the course's rqt_graph, rqt_image_view and
`rosrun actionlib axclient.py` commands run through Debian's tools (rqt_graph writes its picture to a file).
turtlesim_node's line is checked in test_turtlesim_window, tb3_sim's (a world launch) in test_tb3_sim_launch.

One master for the module; every command runs with DISPLAY, WAYLAND_DISPLAY and QT_QPA_PLATFORM unset, as in a
student's terminal on a machine without a screen."""
import subprocess
import time
from pathlib import Path

import pytest
from PIL import Image

from roslab import wait_for_topic, wait_until
from roslab.processes import descendants

HIDDEN = ("DISPLAY", "WAYLAND_DISPLAY", "QT_QPA_PLATFORM")
ERROR_WALLS = ("Traceback", "qt.qpa", "could not connect to display", "Unable to access the X Display")


@pytest.fixture(scope="module")
def headless(ros_master):
    """The module's master, its environment without a display."""
    for name in HIDDEN:
        ros_master.env.pop(name, None)
    return ros_master


def command_line(pid):
    try:
        return Path(f"/proc/{pid}/cmdline").read_bytes()
    except OSError:
        return b""


def run(master, *command, cwd=None):
    result = subprocess.run(command, env=master.env, cwd=cwd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                            text=True, timeout=60)
    return result.returncode, result.stdout


def one_hint(output, tool):
    """The output's single hint line for `tool`, after checking there is exactly one and no error wall."""
    lines = [line for line in output.splitlines() if f"[{tool}] no display, so " in line]
    assert len(lines) == 1, output
    assert not any(wall in output for wall in ERROR_WALLS), output
    assert "xvfb-run -a " in lines[0]
    return lines[0]


def wait_for_hint(process, tool, timeout_s=60):
    wait_until(lambda: f"[{tool}] no display, so " in process.output(), timeout_s, f"{tool}'s no-display line")
    return one_hint(process.output(), tool)


@pytest.mark.parametrize("command, tool", [
    (["rosrun", "rviz", "rviz"], "rviz"),
    (["rosrun", "image_view", "image_view", "image:=/camera/rgb/image_raw"], "image_view"),
    (["rosrun", "rqt_image_view", "rqt_image_view", "/camera/rgb/image_raw"], "rqt_image_view"),
    (["rosrun", "actionlib", "axclient.py", "/turtle_shape"], "axclient"),
    (["rosrun", "actionlib_tools", "axclient.py", "/turtle_shape"], "axclient"),
])
def test_a_window_tool_run_directly_prints_the_line_and_exits(headless, command, tool):
    returncode, output = run(headless, *command)
    line = one_hint(output, tool)
    assert returncode == 0
    assert line.endswith("xvfb-run -a " + " ".join(command)) or tool == "axclient"


def test_the_relay_leaves_debians_actionlib_python_package_and_ros_package_alone(headless):
    code, output = run(headless, "python3", "-c",
                       "import actionlib, actionlib_tools; print(actionlib.__file__, actionlib.SimpleActionClient)")
    assert code == 0 and output.startswith("/usr/lib/python3/dist-packages/actionlib/"), output
    assert run(headless, "rospack", "find", "actionlib") == (0, "/usr/share/actionlib\n")


def test_a_required_rviz_in_a_launch_prints_the_line_and_keeps_the_launch_running(headless):
    launch = headless.roslaunch("tuos_simulations", "rviz.launch")
    try:
        line = wait_for_hint(launch, "rviz")
        assert "lab_web web.launch" in line and "http://localhost:8080" in line
        wait_for_topic(headless.uri, "/tf_static")
        assert launch.running(), launch.output()
    finally:
        launch.stop()


def test_rqt_graph_writes_the_graph_to_a_file_and_prints_where(headless, tmp_path):
    talker = headless.start(["rostopic", "pub", "-r", "5", "/chatter", "std_msgs/String", "data: hi"], "talker")
    listener = headless.start(["rostopic", "echo", "/chatter"], "listener")
    try:
        wait_until(lambda: "data: " in listener.output(), 30, "the listener hearing the talker")
        returncode, output = run(headless, "rosrun", "rqt_graph", "rqt_graph", cwd=tmp_path)
    finally:
        listener.stop()
        talker.stop()
    line = one_hint(output, "rqt_graph")
    assert returncode == 0
    assert f"written to {tmp_path / 'rosgraph.png'}" in line and "graph panel" in line
    assert "1 connections" in line
    with Image.open(tmp_path / "rosgraph.png") as picture:
        assert picture.format == "PNG" and picture.width > 100


def test_rqt_graph_without_a_master_says_so(headless, tmp_path):
    env = dict(headless.env, ROS_MASTER_URI="http://localhost:9")
    result = subprocess.run(["rosrun", "rqt_graph", "rqt_graph"], env=env, cwd=tmp_path, stdout=subprocess.PIPE,
                            stderr=subprocess.STDOUT, text=True, timeout=60)
    assert result.returncode == 1
    assert "[rqt_graph] cannot reach the ROS master at http://localhost:9" in result.stdout
    assert "Traceback" not in result.stdout and not (tmp_path / "rosgraph.png").exists()


def test_with_a_display_rqt_graph_shows_its_window_until_ctrl_c(headless):
    """Under Debian's xvfb-run (a virtual display): no hint line and no error while the window is open; Ctrl-C ends
    it without a Python traceback (xvfb-run's X server ends with it)."""
    graph = headless.start(["xvfb-run", "-a", "rosrun", "rqt_graph", "rqt_graph"], "rqt_graph-xvfb")
    try:
        wait_until(lambda: any(b"rqt_graph/rqt_graph" in command_line(pid) for pid, _ in descendants(graph.pid)),
                   30, "rqt_graph started under xvfb-run")
        time.sleep(3)   # the graph read, drawn and shown: nothing may be printed meanwhile
        assert graph.running(), graph.output()
        assert "[rqt_graph]" not in graph.output() and not any(wall in graph.output() for wall in ERROR_WALLS)
    finally:
        graph.stop()
    assert "Traceback" not in graph.output()
