"""turtlebot3_teleop_key (imports rospy): drive a TurtleBot3 from the keyboard of the terminal it runs in.

Node `turtlebot3_teleop` (the launch file names it turtlebot3_teleop_keyboard).
Publishes geometry_msgs/Twist on `cmd_vel` (relative to the node's namespace, queue 10) once per loop, even
when no key comes: the loop reads one key with a 0.1 s timeout (KEY_TIMEOUT_S, wall clock, as the original's
select), so about 10 Hz while idle and once per key while typing. Only linear.x and angular.z are non-zero.
Parameter `model` (node namespace, not private; default "burger"): burger, waffle or waffle_pi choose the
velocity limits; any other value gets the burger's limits, with a warning. Keys, limits, ramp and printed
text: see keyboard_teleop.

Ending: Ctrl-C (a key in the raw terminal), SIGINT or SIGTERM (e.g. from roslaunch), `rosnode kill` or the
terminal going away end the loop; the node then publishes one zero Twist and restores the terminal settings
it found. An unexpected error prints `Communications Failed` with the reason (no traceback) and exits with 1,
also after stopping the robot and restoring the terminal. Without a terminal on stdin (piped, or started by roslaunch
from something that is not a terminal) it prints one line saying so and exits with 1. Before the master
answers, rospy waits for it (and says so); Ctrl-C then quits quietly.
"""
import sys

import rosgraph
import rospy

from stop_request import StopRequest
from tb3_client.commands import CommandPublisher

from .key_terminal import KeyTerminal, NotATerminalError
from .keyboard_teleop import (
    BANNER,
    DEFAULT_MODEL,
    MODEL_LIMITS,
    KeyboardTeleop,
    is_known_model,
    is_quit,
    limits_for_model,
)

NODE_NAME = "turtlebot3_teleop"
MODEL_PARAM = "model"
KEY_TIMEOUT_S = 0.1
"""How long one loop waits for a key [s, wall clock]."""

NOT_A_TERMINAL = ("turtlebot3_teleop_key: standard input is not a terminal, so there are no keys to read; run it "
                  "in a terminal window: rosrun turtlebot3_teleop turtlebot3_teleop_key (or roslaunch "
                  "turtlebot3_teleop turtlebot3_teleop_key.launch)")


def read_model():
    """The `model` parameter (DEFAULT_MODEL when unset); warns when it is not a model with its own limits."""
    model = rospy.get_param(MODEL_PARAM, DEFAULT_MODEL)
    if not is_known_model(model):
        rospy.logwarn("%s is %r, which is not one of %s: using the burger's velocity limits",
                      rospy.resolve_name(MODEL_PARAM), model, ", ".join(MODEL_LIMITS))
    return model


def say(text):
    print(text, flush=True)


class TeleopKeyNode:
    """Wires keys from a KeyTerminal through a KeyboardTeleop to the cmd_vel publisher."""

    def __init__(self, teleop):
        self._teleop = teleop
        self._cmd_vel = CommandPublisher("cmd_vel", queue_size=10)
        rospy.on_shutdown(self.stop_robot)   # `rosnode kill` shuts rospy down from another thread

    def run(self, keys, stop):
        """One loop per key read until Ctrl-C, `stop`, ROS shutdown or the end of the terminal's input."""
        while not (stop.is_set() or rospy.is_shutdown()):
            try:
                key = keys.read_key(KEY_TIMEOUT_S)
            except EOFError:
                return
            if is_quit(key):
                return
            for line in self._teleop.press(key):
                say(line)
            if not self._cmd_vel.publish(*self._teleop.step()):
                return

    def stop_robot(self):
        """Publish one zero Twist as the last command and give it time to leave (the loop and rospy's shutdown
        hook may both call it)."""
        self._cmd_vel.stop_for_good()


def main():
    """Run the node; returns the exit code."""
    try:
        terminal = KeyTerminal(sys.stdin.fileno())
    except (NotATerminalError, AttributeError, ValueError, OSError):
        print(NOT_A_TERMINAL, file=sys.stderr)
        return 1
    try:
        rospy.init_node(NODE_NAME, disable_signals=True)   # waits for the master, if need be
        model = read_model()
    except KeyboardInterrupt:
        return 0   # Ctrl-C while waiting for the master: nothing has started yet
    except OSError as error:
        print("turtlebot3_teleop_key: cannot reach the ROS master at {} ({}); start roscore first".format(
            rosgraph.get_master_uri(), error), file=sys.stderr)
        return 1
    stop = StopRequest()
    stop.install()
    node = TeleopKeyNode(KeyboardTeleop(limits_for_model(model)))
    exit_code = 0
    try:
        say(BANNER)
        with terminal as keys:
            node.run(keys, stop)
    except Exception as error:  # reported in one line: the terminal is a user's, not a debugger's
        say("\nCommunications Failed: {}: {}\n".format(type(error).__name__, error))
        exit_code = 1
    finally:
        node.stop_robot()
        rospy.signal_shutdown("turtlebot3_teleop_key finished")
    return exit_code
