"""scripts/demo, the README's main command: it runs the Week 4 tour against tb3_sim, prints the table,
writes a top-down PNG showing the trajectory, and exits 0 leaving nothing running."""
import os
import re
import signal
import subprocess
from pathlib import Path

import cv2
import numpy as np
import pytest

from roslab import free_port
from roslab.http_check import http_status

REPO_ROOT = Path(__file__).resolve().parents[3]
PICTURE = REPO_ROOT / "demo-output" / "week4_demo.png"
TRAIL_PIXELS_AT_LEAST = 100


def is_trail_blue(rgb):
    """Which pixels of `rgb` (rows, columns, 3) have the renderer's trail colour (120, 180, 230), also where a
    translucent red laser ray crosses it: a boolean array of (rows, columns)."""
    red, green, blue = (rgb[..., channel].astype(int) for channel in range(3))
    return (blue >= 170) & (blue - red >= 40) & (green >= 120)


@pytest.fixture(scope="module")
def demo_run(tmp_path_factory):
    home = tmp_path_factory.mktemp("demo")
    env = dict(os.environ, ROS_MASTER_URI="http://localhost:{}".format(free_port()), ROS_HOSTNAME="localhost",
               ROS_HOME=str(home), ROS_LOG_DIR=str(home / "log"))
    env.pop("DISPLAY", None)
    result = subprocess.run([str(REPO_ROOT / "scripts" / "demo"), "--rtf", "3"], env=env, stdout=subprocess.PIPE,
                            stderr=subprocess.STDOUT, text=True, timeout=600, start_new_session=True)
    result.master_uri = env["ROS_MASTER_URI"]
    return result


def processes_using(master_uri):
    """Pids of the processes whose environment points at `master_uri` (the demo's roscore and nodes)."""
    marker = ("ROS_MASTER_URI=" + master_uri).encode()
    pids = []
    for environ in Path("/proc").glob("[0-9]*/environ"):
        try:
            if marker in environ.read_bytes().split(b"\0"):
                pids.append(int(environ.parent.name))
        except OSError:   # gone meanwhile, or not ours to read
            pass
    return pids


def test_demo_exits_0_with_the_table(demo_run):
    assert demo_run.returncode == 0, demo_run.stdout[-3000:]
    output = demo_run.stdout
    assert "measured from /odom and /scan" in output
    first_row = next(line for line in output.splitlines() if line.startswith("1  /move_service True"))
    moved = float(re.search(r"moved ([+-][0-9.]+) m", first_row).group(1))
    assert moved == pytest.approx(0.50, abs=0.03)
    assert "Request failed: approach_velocity 0.5 must be in (0, 0.26]" in output
    assert "top-down picture of the run" in output


def test_demo_picture_shows_the_trajectory(demo_run):
    image = cv2.imread(str(PICTURE), cv2.IMREAD_COLOR)
    assert image is not None, "no PNG at {}".format(PICTURE)
    trail = int(np.count_nonzero(is_trail_blue(cv2.cvtColor(image, cv2.COLOR_BGR2RGB))))
    assert trail >= TRAIL_PIXELS_AT_LEAST


def test_demo_prints_no_false_warnings(demo_run):
    """Nothing was restarted and the tour starts once the master is up: neither rospy's complaint about a master
    not running yet nor master_reconnect's re-registration line, in the demo's output or its launch log."""
    launch_log = (REPO_ROOT / "demo-output" / "week4_demo_launch.log").read_text()
    for text in ("Unable to register", "Unable to immediately register", "re-registered"):
        assert text not in demo_run.stdout, demo_run.stdout
        assert text not in launch_log, launch_log


def test_demo_leaves_no_process_behind(demo_run):
    """No process of the demo's (they all carry its private ROS_MASTER_URI) outlives it; other test modules' ROS
    processes, running in parallel, are not the demo's."""
    assert processes_using(demo_run.master_uri) == []


def test_demo_web_prints_the_address_while_it_runs(tmp_path):
    """`scripts/demo --web` prints the browser view's address as soon as the page is up, before the tour's table:
    the node's output reaches the log line by line (it used to arrive in one block at shutdown, and the address
    was never shown). The printed address serves the page; Ctrl-C then ends everything."""
    env = dict(os.environ, ROS_MASTER_URI="http://localhost:{}".format(free_port()), ROS_HOSTNAME="localhost",
               ROS_HOME=str(tmp_path), ROS_LOG_DIR=str(tmp_path / "log"))
    env.pop("DISPLAY", None)
    web_port = free_port()
    demo = subprocess.Popen([str(REPO_ROOT / "scripts" / "demo"), "--web", "--web-port", str(web_port)], env=env,
                            stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, start_new_session=True)
    seen = []
    try:
        for line in demo.stdout:
            seen.append(line)
            if "the browser view:" in line or "measured from /odom" in line:
                break
        address = re.search(r"the browser view: open (http://\S+) in a browser", "".join(seen))
        assert address, "".join(seen)
        assert address.group(1) == "http://localhost:{}/".format(web_port)
        assert http_status(address.group(1), timeout_s=10.0) == 200
    finally:
        os.killpg(demo.pid, signal.SIGINT)
        demo.communicate(timeout=60)
    assert processes_using(env["ROS_MASTER_URI"]) == []
