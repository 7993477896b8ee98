"""Console lines in roscpp's format for rospy nodes (imports rospy), as the original C++ nodes print them.

rospy's console handler (rosgraph.roslogging.RosStreamHandler, set up by rospy.init_node from
python_logging.conf) is swapped for RoscppConsoleHandler on the `rosout` logger. Only the terminal output
changes: the log file and /rosout get the same records as before.
"""
import logging
import os
import sys
import threading
import time

import rospy
from rosgraph.roslogging import RosStreamHandler

from roscpp_console.line_format import DEFAULT_FORMAT, SEVERITIES, console_line, stamp_text

COLORS = {'DEBUG': '\033[32m', 'WARNING': '\033[33m', 'ERROR': '\033[31m', 'CRITICAL': '\033[31m'}
"""rosconsole's colours (green, yellow, red), used only when the stream is a terminal."""
COLOR_RESET = '\033[0m'


class RoscppConsoleHandler(logging.Handler):
    """Writes each record as one roscpp console line: below WARNING to stdout, the rest to stderr, coloured
    as rosconsole colours them when the stream is a terminal."""

    def __init__(self):
        super().__init__()
        self._formatter = logging.Formatter()

    def emit(self, record):
        tokens = {
            'severity': SEVERITIES[record.levelname],
            'message': self._formatter.format(record),
            'time': ros_time_text(),
            'walltime': stamp_text(time.time_ns()),
            'node': rospy.get_name(),
            'logger': record.name,
            'file': record.pathname,
            'line': record.lineno,
            'function': record.funcName,
            'thread': threading.get_ident(),
        }
        line = console_line(os.environ.get('ROSCONSOLE_FORMAT', DEFAULT_FORMAT), tokens)
        stream = sys.stdout if record.levelno < logging.WARNING else sys.stderr
        color = COLORS.get(record.levelname)
        if color and stream.isatty():
            line = color + line + COLOR_RESET
        stream.write(line + '\n')
        stream.flush()


def ros_time_text():
    """roscpp's ${time}: the wall time, then `, <ROS time>` when the node runs on simulated time."""
    text = stamp_text(time.time_ns())
    if not rospy.rostime.is_wallclock():
        text += ', ' + stamp_text(rospy.get_rostime().to_nsec())
    return text


def use_roscpp_console():
    """Replace rospy's console handler on the `rosout` logger by RoscppConsoleHandler (at the same level).
    Call right after rospy.init_node."""
    logger = logging.getLogger('rosout')
    for handler in list(logger.handlers):
        if isinstance(handler, RosStreamHandler):
            replacement = RoscppConsoleHandler()
            replacement.setLevel(handler.level)
            logger.removeHandler(handler)
            logger.addHandler(replacement)
