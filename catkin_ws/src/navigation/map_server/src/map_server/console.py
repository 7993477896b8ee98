"""Console lines in roscpp's format (`[ INFO] [1700000000.123456789]: ...`), as the C++ map_server and map_saver
print them: turtlesim's handler for rospy's records after init_node, and the same line for the argument errors
the originals report before they contact the master (they need none)."""

import os
import sys
import time

from turtlesim.core.console import DEFAULT_FORMAT, SEVERITIES, console_line, stamp_text
from turtlesim.ros.console import use_roscpp_console

__all__ = ["error_line", "use_roscpp_console"]


def error_line(text):
    """An ERROR line on stderr, before rospy.init_node (wall time, as roscpp prints it)."""
    tokens = {"severity": SEVERITIES["ERROR"], "message": text, "time": stamp_text(time.time_ns()),
              "walltime": stamp_text(time.time_ns())}
    sys.stderr.write(console_line(os.environ.get("ROSCONSOLE_FORMAT", DEFAULT_FORMAT), tokens) + "\n")
