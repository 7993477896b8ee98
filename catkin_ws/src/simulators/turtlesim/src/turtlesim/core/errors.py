"""Exceptions of the turtlesim core. The ROS adapter catches TurtleSimError once.

Every error carries the text the original logs (or roscpp throws) and the level it is logged at.
The core does not log a failure itself: the adapter logs `str(error)` at `error.level` and fails
the service call (returns False / raises rospy.ServiceException with an empty message for the
`returns_false` errors, or with the text for exceptions roscpp would have thrown).
"""
from turtlesim.core.log import LogLevel


class TurtleSimError(Exception):
    """Root of all failures of the core.

    Attributes:
        level: the log level the original uses for this text.
        returns_false: True when the original's callback returns false (the client sees
            `responded with an error: b''`); False when roscpp throws and the client sees the text.
    """

    level = LogLevel.ERROR
    returns_false = True


class DuplicateNameError(TurtleSimError):
    """Spawn with a non-empty name that already exists (the original's "turtled" typo kept)."""

    def __init__(self, name):
        super().__init__('A turtled named [%s] already exists' % name)


class UnknownTurtleError(TurtleSimError):
    """Kill, or a per-turtle request, for a name that does not exist."""


class InvalidNameError(TurtleSimError):
    """Spawn name that is not a ROS graph resource name; roscpp's InvalidNameException text."""

    returns_false = False


class NonFiniteValueError(TurtleSimError):
    """A request value is NaN or infinite (or overflows float32). Not in the original, which
    would corrupt the turtle; the replica rejects the request and logs a warning instead."""

    level = LogLevel.WARN
    returns_false = False
