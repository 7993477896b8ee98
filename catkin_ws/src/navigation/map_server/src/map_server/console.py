"""An ERROR line before the node exists, formatted as rospy prints one after init_node, for the argument errors
the originals report before they contact the master (they need none)."""

import sys
import time


def error_line(text, stream=None):
    (stream or sys.stderr).write("[ERROR] [{:.6f}]: {}\n".format(time.time(), text))
