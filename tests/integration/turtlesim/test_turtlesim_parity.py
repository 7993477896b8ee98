"""turtlesim_node as a user of the original sees it: `rosservice list` and `rosnode info` show the original's
services (the replica's snapshot service is off unless ~snapshot_service is true), console lines are in
roscpp's format, and a call that fails inside the client leaves no line in turtlesim's terminal."""
import re
import subprocess

import pytest

from roslab import wait_for_service, wait_for_topic, wait_until

ORIGINAL_SERVICE_LIST = [
    "/clear", "/kill", "/reset", "/rosout/get_loggers", "/rosout/set_logger_level", "/spawn",
    "/turtle1/set_pen", "/turtle1/teleport_absolute", "/turtle1/teleport_relative",
    "/turtlesim/get_loggers", "/turtlesim/set_logger_level",
]
"""`rosservice list` with roscore and the original turtlesim_node running (turtlesim spec 1.4, 1.5 and 1.1:
the global and turtle1's services, roscpp's two logger services; rosout's two come from roscore)."""

ROSCPP_LINE = r"\[(?: INFO| WARN|ERROR)\] \[\d+\.\d{9}\]: "


def run(master, *command):
    result = subprocess.run(list(command), env=master.env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                            text=True, timeout=30)
    return result.returncode, result.stdout


@pytest.fixture(scope="module")
def sim(ros_master):
    process = ros_master.rosrun("turtlesim", "turtlesim_node", "_headless:=true")
    wait_for_service(ros_master.uri, "/turtle1/teleport_absolute")
    wait_for_topic(ros_master.uri, "/turtle1/pose")
    return process


def test_rosservice_list_is_the_originals(ros_master, sim):
    code, output = run(ros_master, "rosservice", "list")
    assert code == 0, output
    assert output.split() == ORIGINAL_SERVICE_LIST


def test_rosnode_info_lists_the_originals_services(ros_master, sim):
    code, output = run(ros_master, "rosnode", "info", "/turtlesim")
    assert code == 0, output
    services = output.split("Services: \n", 1)[1].split("\n\n", 1)[0]
    assert [line.strip(" *") for line in services.splitlines()] == [
        "/clear", "/kill", "/reset", "/spawn", "/turtle1/set_pen", "/turtle1/teleport_absolute",
        "/turtle1/teleport_relative", "/turtlesim/get_loggers", "/turtlesim/set_logger_level"]


def test_console_lines_are_in_roscpps_format(ros_master, sim):
    run(ros_master, "rosservice", "call", "/kill", "name: nobody")
    run(ros_master, "rosservice", "call", "/turtle1/teleport_absolute", "20", "5", "0")
    wait_until(lambda: "Oh no! I hit the wall!" in sim.output(), 10, "the wall warning")
    lines = sim.output().splitlines()
    assert re.fullmatch(ROSCPP_LINE + r"Starting turtlesim with node name /turtlesim", lines[0]), lines[0]
    assert re.fullmatch(ROSCPP_LINE + r"Spawning turtle \[turtle1\] at x=\[5\.544445\], y=\[5\.544445\], "
                        r"theta=\[0\.000000\]", lines[1]), lines[1]
    assert any(re.fullmatch(r"\[ERROR\] \[\d+\.\d{9}\]: Tried to kill turtle \[nobody\], which does not exist",
                            line) for line in lines), lines
    assert any(re.fullmatch(r"\[ WARN\] \[\d+\.\d{9}\]: Oh no! I hit the wall! \(Clamping from \[x=20\.000000, "
                            r"y=6\.088889\]\)", line) for line in lines), lines
    assert all(re.match(ROSCPP_LINE, line) for line in lines), lines


def test_a_call_that_fails_in_the_client_logs_nothing(ros_master, sim):
    """rosservice connects, cannot serialise the request and hangs up: roscpp logs nothing (rospy.Service
    would log 'incoming connection failed'). The /kill after it is the marker: its line comes next."""
    before = sim.output()
    code, output = run(ros_master, "rosservice", "call", "/spawn", "{x: abc}")
    assert code != 0 and "field x must be float type" in output
    run(ros_master, "rosservice", "call", "/kill", "name: marker")
    wait_until(lambda: "[marker]" in sim.output(), 10, "the marker's error line")
    new_lines = sim.output()[len(before):].splitlines()
    assert len(new_lines) == 1 and new_lines[0].endswith("Tried to kill turtle [marker], which does not exist")


def test_the_snapshot_service_is_there_when_asked_for(ros_master, sim):
    ros_master.rosrun("turtlesim", "turtlesim_node", "_headless:=true", "_snapshot_service:=true", "__ns:=/snap")
    wait_for_service(ros_master.uri, "/snap/turtlesim/snapshot")


def test_a_bad_snapshot_service_value_is_a_clear_error(ros_master, sim):
    process = ros_master.rosrun("turtlesim", "turtlesim_node", "_headless:=true", "_snapshot_service:=maybe",
                                "__ns:=/bad")
    wait_until(lambda: not process.running(), 20, "turtlesim_node to exit")
    assert process.popen.returncode == 2
    assert "Parameter /bad/turtlesim/snapshot_service must be true or false, got 'maybe'" in process.output()
    assert "Traceback" not in process.output()
