"""roscpp's console line format (rosconsole), which the C++ originals the lab stands in for print.

roscpp prints `[ INFO] [1700000000.123456789]: text`: the severity padded to five characters, the wall time
as seconds and nine digits of nanoseconds, and `, <ROS time>` after it when the node runs on simulated time.
rospy prints `[INFO] [1700000000.123456]: text` instead. ROSCONSOLE_FORMAT replaces the default format in
both; the tokens roscpp documents are filled here: ${severity}, ${message}, ${time}, ${walltime}, ${node},
${logger}, ${file}, ${line}, ${function} and ${thread}.
"""
import os
import re
import sys
import time

DEFAULT_FORMAT = '[${severity}] [${time}]: ${message}'
"""roscpp's format when ROSCONSOLE_FORMAT is not set."""

SEVERITIES = {'DEBUG': 'DEBUG', 'INFO': ' INFO', 'WARNING': ' WARN', 'ERROR': 'ERROR', 'CRITICAL': 'FATAL'}
"""Python logging level name -> roscpp's ${severity} text."""

_TOKEN = re.compile(r'\$\{(\w+)\}')


def stamp_text(nanoseconds):
    """A time in integer nanoseconds as roscpp prints a ros::Time: seconds, a dot, nine digits."""
    seconds, rest = divmod(nanoseconds, 1_000_000_000)
    return '%d.%09d' % (seconds, rest)


def console_line(line_format, tokens):
    """`line_format` with each ${token} of `tokens` (name -> text) filled in; unknown tokens stay as
    they are."""
    return _TOKEN.sub(lambda match: str(tokens.get(match.group(1), match.group(0))), line_format)


def error_line(text):
    """Writes an ERROR line to stderr as a C++ node prints it before it contacts the master (map_server's and
    map_saver's argument errors): wall time, ROSCONSOLE_FORMAT honoured."""
    now = stamp_text(time.time_ns())
    tokens = {"severity": SEVERITIES["ERROR"], "message": text, "time": now, "walltime": now}
    sys.stderr.write(console_line(os.environ.get("ROSCONSOLE_FORMAT", DEFAULT_FORMAT), tokens) + "\n")
