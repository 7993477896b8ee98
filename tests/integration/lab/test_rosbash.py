"""rosbash in a ROS terminal, typed into a real interactive bash in a pseudo-terminal whose .bashrc sources
scripts/env.sh: roscd, rosls, rosed, roscp, rospd, rosd (Debian's rosbash file) and Tab completion of ROS names
and packages and of other commands (Debian's bash-completion). HOME is a temporary folder."""
import subprocess
from pathlib import Path

import pytest

REPO_ROOT = Path(__file__).resolve().parents[3]
TUOS_MSGS = REPO_ROOT / "catkin_ws/src/interfaces/tuos_msgs"
WEEK4_SERVICES = REPO_ROOT / "catkin_ws/src/exercises/week4_services"


def test_roscd_and_rosls(terminal):
    assert terminal.run("roscd tuos_msgs && pwd").strip() == str(TUOS_MSGS)
    assert terminal.run("rosls tuos_msgs/srv").split() == ["Approach.srv", "SetBool.srv", "TimedMovement.srv"]


def test_roscd_log_goes_to_the_log_folder_of_the_running_master(ros_master, terminal):
    run_id = subprocess.run(["rosparam", "get", "/run_id"], env=ros_master.env, stdout=subprocess.PIPE, text=True,
                            timeout=30).stdout.strip()
    assert terminal.run("roscd log && pwd").strip() == str(ros_master.workdir / "log" / run_id)


def test_rosed_opens_a_package_file_in_the_editor(terminal):
    output = terminal.run("EDITOR=cat rosed tuos_msgs SetBool.srv")
    assert output == (TUOS_MSGS / "srv" / "SetBool.srv").read_text()


def test_roscp_copies_a_package_file(home, terminal):
    terminal.run("roscp week4_services week4_demo.launch ~/copy.launch")
    assert (home / "copy.launch").read_text() == (WEEK4_SERVICES / "launch" / "week4_demo.launch").read_text()


def test_rospd_and_rosd_remember_folders(terminal):
    terminal.run("cd / && dirs -c")
    terminal.run("rospd tuos_msgs")
    output = terminal.run("rospd week4_services")
    assert output.splitlines() == ["0 {}".format(WEEK4_SERVICES), "1 {}".format(TUOS_MSGS), "2 /"]
    assert terminal.run("rosd").splitlines() == output.splitlines()
    terminal.run("rospd 2")
    assert terminal.run("pwd").strip() == "/"


@pytest.mark.parametrize("typed, completed", [
    ("roscd tuos_ms", "tuos_msgs/"),
    ("rosls week4_services/no", "week4_services/nodes/"),
    ("rosrun week4_ser", "week4_services "),
    ("rosrun week4_services approach_s", "approach_server.py "),
    ("roslaunch week4_services week4_demo.", "week4_demo.launch "),
    ("rossrv show tuos_msgs/Appr", "tuos_msgs/Approach "),
    ("catkin bui", "build "),   # catkin_tools' completion, loaded on demand by bash-completion
])
def test_tab_completes(terminal, typed, completed):
    terminal.type(typed)
    terminal.tab(completed)
    terminal.discard_line()
