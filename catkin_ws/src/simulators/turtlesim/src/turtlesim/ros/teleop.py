"""turtle_teleop_key (imports rospy): arrow keys in the terminal drive turtle1.

Node `teleop_turtle`. Publishes geometry_msgs/Twist on turtle1/cmd_vel (relative to the node
namespace, queue 1): one Twist per arrow key, linear.x = +-scale_linear or angular.z =
+-scale_angular. Params scale_linear and scale_angular (numbers, default 2.0) are read once at
start from the node's namespace, not privately. `q` quits; the terminal is restored on every
exit path (q, Ctrl-C, SIGTERM, end of input). Without a terminal on stdin it says so and exits
with 1; a scale that is not a finite number exits with 2.
"""
import math
import sys

import rospy
from geometry_msgs.msg import Twist

from roscpp_console.handler import use_roscpp_console
from turtlesim.core.teleop_keys import BANNER, DEFAULT_SCALE_ANGULAR, DEFAULT_SCALE_LINEAR, KEY_QUIT, command_for_key
from turtlesim.tools.terminal import RawTerminal

POLL_INTERVAL_S = 0.1
"""How often the key loop checks for ROS shutdown (SIGTERM, rosnode kill) while no key comes."""

NODE_NAME = 'teleop_turtle'

NOT_A_TERMINAL = ('turtle_teleop_key reads arrow keys from a terminal, but its standard input '
                  'is not one. Run it in a terminal of its own: rosrun turtlesim '
                  'turtle_teleop_key')


class ConfigError(ValueError):
    """A parameter has a value the node cannot use; the text names it."""


def read_scale(name, default):
    """Number parameter `name` (node namespace) as a float; ConfigError for anything else,
    including NaN and infinities."""
    value = rospy.get_param(name, default)
    if (isinstance(value, bool) or not isinstance(value, (int, float))
            or not math.isfinite(value)):
        raise ConfigError('%s must be a finite number, got %r' % (rospy.resolve_name(name), value))
    return float(value)


def twist(linear, angular):
    """A Twist with only linear.x and angular.z set."""
    message = Twist()
    message.linear.x = linear
    message.angular.z = angular
    return message


class KeyTeleop:
    """Reads keys from a RawTerminal and publishes one Twist per arrow key."""

    def __init__(self, scale_linear, scale_angular):
        self._scales = (scale_linear, scale_angular)
        self._cmd_vel = rospy.Publisher('turtle1/cmd_vel', Twist, queue_size=1)

    def run(self, keys):
        """Print the banner and handle keys until `q`, end of input or ROS shutdown."""
        print('\n'.join(BANNER), flush=True)
        while not rospy.is_shutdown():
            try:
                byte = keys.read_byte(POLL_INTERVAL_S)
            except EOFError:
                return
            if byte == KEY_QUIT:
                return
            command = None if byte is None else command_for_key(byte, *self._scales)
            if command is not None:
                self._cmd_vel.publish(twist(*command))


def stdin_terminal():
    """A RawTerminal on standard input, or None when stdin is closed or not a terminal."""
    try:
        return RawTerminal(sys.stdin.fileno())
    except (AttributeError, ValueError, OSError):
        return None


def main():
    """Run the node; returns the exit code."""
    terminal = stdin_terminal()
    if terminal is None:
        print(NOT_A_TERMINAL, file=sys.stderr)
        return 1
    rospy.init_node(NODE_NAME)
    use_roscpp_console()
    try:
        teleop = KeyTeleop(read_scale('scale_linear', DEFAULT_SCALE_LINEAR),
                           read_scale('scale_angular', DEFAULT_SCALE_ANGULAR))
    except ConfigError as error:
        rospy.logfatal(str(error))
        return 2
    try:
        with terminal as keys:
            teleop.run(keys)
    except KeyboardInterrupt:
        pass  # Ctrl-C is how a user may quit; the terminal is already restored
    finally:
        rospy.signal_shutdown('teleop finished')
    return 0
