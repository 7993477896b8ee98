"""turtlebot3_teleop_key as a student runs it: typed into an interactive bash in a pseudo-terminal whose .bashrc
sources scripts/env.sh (rosrun and roslaunch), keys in, Twists out on /cmd_vel (watched by the probe), the
status lines on the screen, and the terminal settings as they were afterwards (Ctrl-C and SIGTERM). Without a
terminal the node says so in one line."""
import os
import re
import signal
import subprocess
import termios
from pathlib import Path

import pytest
import rosgraph

from roslab import wait_until
from roslab.processes import descendants
from roslab.terminal import PROMPT

CMD_VEL = "/cmd_vel"
BANNER_END = "CTRL-C to quit"
NOT_A_TERMINAL = "turtlebot3_teleop_key: standard input is not a terminal, so there are no keys to read"
ROSRUN = "rosrun turtlebot3_teleop turtlebot3_teleop_key"
ROSLAUNCH = "roslaunch turtlebot3_teleop turtlebot3_teleop_key.launch"


def status_line(linear, angular):
    """The original's line after a velocity key: the targets as Python prints floats, and a trailing space."""
    return "currently:\tlinear vel {}\t angular vel {} ".format(linear, angular)


# Each key, the status line it prints (targets), and the commands the original publishes on its way to them:
# half a step (0.005 m/s, 0.05 rad/s) per loop; s stops at once. Model burger (no `model` parameter).
KEY_SEQUENCE = [
    ("w", status_line(0.01, 0.0), [(0.005, 0.0), (0.01, 0.0)]),
    ("w", status_line(0.02, 0.0), [(0.015, 0.0), (0.02, 0.0)]),
    ("w", status_line(0.03, 0.0), [(0.025, 0.0), (0.03, 0.0)]),
    ("a", status_line(0.03, 0.1), [(0.03, 0.05), (0.03, 0.1)]),
    ("d", status_line(0.03, 0.0), [(0.03, 0.05), (0.03, 0.0)]),
    ("x", status_line(0.019999999999999997, 0.0), [(0.025, 0.0), (0.02, 0.0)]),
    ("s", status_line(0.0, 0.0), [(0.0, 0.0)]),
]


class CmdVel:
    """Every Twist the probe receives on /cmd_vel, as (linear.x, angular.z) plus the whole message."""

    def __init__(self, probe):
        self._probe = probe
        self.messages = []
        probe.subscribe(CMD_VEL, "geometry_msgs/Twist", wait_s=0.0)

    def fetch(self):
        self.messages.extend(entry["msg"] for entry in self._probe.take(CMD_VEL))
        return self.messages

    def commands(self):
        return [(msg["linear"]["x"], msg["angular"]["z"]) for msg in self.fetch()]

    def wait_for_command(self, command, timeout_s=20.0):
        """Wait until the newest Twist is `command` (linear.x, angular.z)."""
        def arrived():
            commands = self.commands()
            return commands and commands[-1] == pytest.approx(command, abs=1e-9)
        wait_until(arrived, timeout_s, "Twist {} on {}".format(command, CMD_VEL), interval_s=0.02)

    def clear(self):
        self.fetch()
        self.messages = []


@pytest.fixture(scope="module")
def cmd_vel(probe):
    return CmdVel(probe)


def master(ros_master):
    return rosgraph.Master("/teleop_test", master_uri=ros_master.uri)


def forget_model(ros_master):
    if master(ros_master).hasParam("/model"):
        master(ros_master).deleteParam("/model")


def canonical(terminal):
    """True when the pseudo-terminal is in canonical (line) mode (tcgetattr on the pty's controlling side
    reports the terminal side's settings)."""
    return bool(termios.tcgetattr(terminal.shell.child_fd)[3] & termios.ICANON)


def start(terminal, command, cmd_vel):
    """Type `command` and wait for the banner and the first Twist (published every loop, key or not)."""
    cmd_vel.clear()
    terminal.type(command + "\r")
    terminal.wait_for(re.escape(BANNER_END), timeout_s=60)
    wait_until(cmd_vel.fetch, 30, "the first Twist on " + CMD_VEL)
    assert not canonical(terminal), "keys are read one at a time"


def press(terminal, cmd_vel, key, line, commands):
    terminal.type(key)
    terminal.wait_for(re.escape(line))
    cmd_vel.wait_for_command(commands[-1])


def deduplicated(commands):
    return [command for index, command in enumerate(commands) if index == 0 or command != commands[index - 1]]


def teleop_pid(terminal):
    """The pid of the node's Python process among the shell's descendants."""
    for pid, _ in descendants(terminal.shell.pid):
        try:
            cmdline = Path("/proc/{}/cmdline".format(pid)).read_bytes()
        except OSError:
            continue
        if b"python" in cmdline and b"turtlebot3_teleop_key" in cmdline:
            return pid
    return None


def shown(terminal):
    """Everything the terminal has shown so far, as it came (CR LF line ends)."""
    terminal.shell.logfile_read.flush()
    return Path(terminal.shell.logfile_read.name).read_text()


def screen(terminal, since=0):
    """What the terminal has shown from character `since` of `shown()` on, with plain newlines."""
    return shown(terminal)[since:].replace("\r\n", "\n")


def assert_stopped_last(cmd_vel):
    last = cmd_vel.fetch()[-1]
    assert last == {"linear": {"x": 0.0, "y": 0.0, "z": 0.0}, "angular": {"x": 0.0, "y": 0.0, "z": 0.0}}


def test_rosrun_keys_give_the_originals_twists_and_ctrl_c_restores_the_terminal(ros_master, terminal, cmd_vel):
    forget_model(ros_master)
    settings = terminal.run("stty -a")
    shown_before = len(shown(terminal))
    start(terminal, ROSRUN, cmd_vel)
    for key, line, commands in KEY_SEQUENCE:
        press(terminal, cmd_vel, key, line, commands)
    expected = [(0.0, 0.0)] + [command for _, _, commands in KEY_SEQUENCE for command in commands]
    assert deduplicated(cmd_vel.commands()) == [pytest.approx(command, abs=1e-9) for command in expected]

    cmd_vel.clear()
    stopped_at = len(cmd_vel.fetch())
    wait_until(lambda: len(cmd_vel.fetch()) >= stopped_at + 5, 10, "Twists while no key is pressed")
    assert set(cmd_vel.commands()) == {(0.0, 0.0)}

    terminal.interrupt(timeout_s=30)
    assert terminal.run("echo $?").strip() == "0"
    assert_stopped_last(cmd_vel)
    assert terminal.run("stty -a") == settings

    text = screen(terminal, since=shown_before)
    status_lines = [line for line in text.split("\n") if line.startswith("currently:")]
    assert status_lines == [line for _, line, _ in KEY_SEQUENCE], "one status line per key, in order"
    assert "Traceback" not in text


def test_roslaunch_without_turtlebot3_model_uses_the_waffle_limits(ros_master, terminal, cmd_vel):
    forget_model(ros_master)
    settings = terminal.run("stty -a")
    start(terminal, "env -u TURTLEBOT3_MODEL " + ROSLAUNCH, cmd_vel)
    assert master(ros_master).getParam("/model") == "waffle"
    assert master(ros_master).lookupNode("/turtlebot3_teleop_keyboard"), "the launch file's node name"
    terminal.type("a" * 20)   # 18 presses reach 1.8000000000000005; the limit holds the 19th and 20th at 1.82
    terminal.wait_for(re.escape(status_line(0.0, 1.8000000000000005)))
    clamped = re.escape(status_line(0.0, 1.82)) + r"\r\n"
    terminal.wait_for(clamped + clamped + r"\r\nControl Your TurtleBot3!")   # and the banner after 20 presses
    cmd_vel.wait_for_command((0.0, 1.82), timeout_s=30)
    assert max(angular for _, angular in cmd_vel.commands()) == 1.82

    terminal.type("\x03")
    terminal.wait_for("all processes on machine have died, roslaunch will exit", timeout_s=30)
    terminal.wait_for(re.escape(PROMPT), timeout_s=30)
    assert_stopped_last(cmd_vel)
    assert terminal.run("stty -a") == settings


@pytest.mark.parametrize("how", ["SIGTERM", "rosnode kill"])
def test_ending_from_outside_stops_the_robot_and_restores_the_terminal(ros_master, terminal, cmd_vel, how):
    master(ros_master).setParam("/model", "tank")
    settings = terminal.run("stty -a")
    shown_before = len(shown(terminal))
    try:
        start(terminal, ROSRUN, cmd_vel)
    finally:
        forget_model(ros_master)
    warning = "/model is 'tank', which is not one of burger, waffle, waffle_pi: using the burger's velocity limits"
    assert warning in screen(terminal, since=shown_before)
    terminal.type("w")
    cmd_vel.wait_for_command((0.01, 0.0))
    if how == "SIGTERM":
        os.kill(wait_until(lambda: teleop_pid(terminal), 10, "the teleop's process"), signal.SIGTERM)
    else:
        subprocess.run(["rosnode", "kill", "/turtlebot3_teleop"], env=ros_master.env, check=True, timeout=30,
                       stdout=subprocess.DEVNULL)
    terminal.wait_for(re.escape(PROMPT), timeout_s=30)
    assert_stopped_last(cmd_vel)
    assert terminal.run("stty -a") == settings


def test_without_a_terminal_it_says_so_in_one_line(ros_master, terminal):
    teleop = ros_master.rosrun("turtlebot3_teleop", "turtlebot3_teleop_key")
    assert teleop.popen.wait(timeout=30) == 1
    assert teleop.output().strip() == NOT_A_TERMINAL + ("; run it in a terminal window: rosrun turtlebot3_teleop "
                                                        "turtlebot3_teleop_key (or roslaunch turtlebot3_teleop "
                                                        "turtlebot3_teleop_key.launch)")

    piped = terminal.run("echo w | " + ROSRUN + "; echo exit=$?", timeout_s=60)
    assert NOT_A_TERMINAL in piped and "exit=1" in piped and "Traceback" not in piped

    launch = ros_master.roslaunch("turtlebot3_teleop", "turtlebot3_teleop_key.launch")
    try:
        launch.popen.wait(timeout=60)   # roslaunch ends by itself once its only node has exited
    except subprocess.TimeoutExpired:
        pytest.fail("roslaunch kept running:\n" + launch.output())
    output = launch.output()
    assert NOT_A_TERMINAL in output and "Traceback" not in output
