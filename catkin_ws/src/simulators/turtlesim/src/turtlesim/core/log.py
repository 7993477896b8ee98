"""Log events of the core: a level and the original's exact text.

The core never imports a logging framework. Objects that log take a `log` sink: any callable
`log(level, text)`. The ROS adapter maps LogLevel.INFO/WARN/ERROR to rospy.loginfo/logwarn/logerr.
"""
import enum
from typing import Callable


class LogLevel(enum.Enum):
    """Severity of a log line, matching the ROS_INFO / ROS_WARN / ROS_ERROR macros used."""

    INFO = 'info'
    WARN = 'warn'
    ERROR = 'error'


LogSink = Callable[[LogLevel, str], None]
"""Signature of a log sink: called once per log line, in the order the original logs them."""
