"""roscpp's console line format (rosconsole), which every node of the original turtlesim package prints.

roscpp prints `[ INFO] [1700000000.123456789]: text`: the severity padded to five characters, the wall time
as seconds and nine digits of nanoseconds, and `, <ROS time>` after it when the node runs on simulated time.
rospy prints `[INFO] [1700000000.123456]: text` instead. ROSCONSOLE_FORMAT replaces the default format in
both; the tokens roscpp documents are filled here: ${severity}, ${message}, ${time}, ${walltime}, ${node},
${logger}, ${file}, ${line}, ${function} and ${thread}.
"""
import re

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
