"""turtle_teleop_key's key table (tutorials/teleop_turtle_key.cpp), no ROS and no tty.

The original reads one byte at a time and matches that byte alone: an arrow key sends
ESC '[' X and only X matters, so typed uppercase A/B/C/D also drive (quirk kept).
"""
KEY_UP = 0x41
KEY_DOWN = 0x42
KEY_RIGHT = 0x43
KEY_LEFT = 0x44
KEY_QUIT = 0x71
"""'q': restore the terminal and exit; publishes nothing."""

KEY_DIRECTIONS = {
    KEY_UP: (1.0, 0.0),
    KEY_DOWN: (-1.0, 0.0),
    KEY_LEFT: (0.0, 1.0),
    KEY_RIGHT: (0.0, -1.0),
}
"""Byte -> (linear, angular) unit command; multiplied by scale_linear / scale_angular."""

DEFAULT_SCALE_LINEAR = 2.0
DEFAULT_SCALE_ANGULAR = 2.0
"""Defaults of the public (node-namespace) params scale_linear / scale_angular."""

BANNER = (
    'Reading from keyboard',
    '---------------------------',
    "Use arrow keys to move the turtle. 'q' to quit.",
)
"""Lines printed at start, in order."""


def command_for_key(byte, scale_linear=DEFAULT_SCALE_LINEAR,
                    scale_angular=DEFAULT_SCALE_ANGULAR):
    """Return (linear.x, angular.z) for one input byte (int), or None for a byte that
    publishes nothing. Each matching byte publishes exactly one Twist, other fields 0."""
    direction = KEY_DIRECTIONS.get(byte)
    if direction is None:
        return None
    linear, angular = direction
    return scale_linear * linear, scale_angular * angular
