"""Reading a student's logs for a marker (plain Python): the traceback a node died with, and the error lines of a
failed catkin build, so that a report says "SyntaxError: Missing parentheses in call to 'print'" instead of a
timeout, and shows catkin's errors instead of the last screen of its output."""
import re

TRACEBACK_START = "Traceback (most recent call last):"
FILE_LINE = re.compile(r'^  File "[^"]*", line \d+')
EXCEPTION_LINE = re.compile(r"^[A-Za-z_][\w.]*(Error|Exception|Exit|Interrupt|Warning)\b.*")
BUILD_ERROR = re.compile(r"(CMake Error|error:|Error \d+|\*\*\*|Parse error|No such file|Invoking .* failed)")
MAX_TRACEBACK_LINES = 60
BUILD_CONTEXT_LINES = 2
MAX_BUILD_ERROR_LINES = 40


def traceback_of(log_text):
    """(the last line of the last traceback: the exception and its message, the traceback as text), or (None, None)
    when the log holds none. A SyntaxError raised while Python compiles a script has no "Traceback" header: its
    `  File "...", line N` block counts from its first line."""
    lines = log_text.splitlines()
    start = None
    for index, line in enumerate(lines):
        if line.startswith(TRACEBACK_START):
            start = index
        elif FILE_LINE.match(line) and (index == 0 or not (lines[index - 1].startswith("  ")
                                                          or lines[index - 1].startswith(TRACEBACK_START))):
            start = index
    if start is None:
        return None, None
    block = lines[start:]
    last = next((line for line in reversed(block) if EXCEPTION_LINE.match(line)), None)
    if last is None:
        return None, None
    end = len(block) - block[::-1].index(last)
    block = block[:end]
    return last.strip(), "\n".join(block[-MAX_TRACEBACK_LINES:])


def build_errors(log_text):
    """The lines of a catkin_make log that say what failed, each with BUILD_CONTEXT_LINES lines after it, in order
    and without repeats (at most MAX_BUILD_ERROR_LINES)."""
    lines = log_text.splitlines()
    keep = []
    for index, line in enumerate(lines):
        if BUILD_ERROR.search(line):
            keep.extend(range(index, min(len(lines), index + 1 + BUILD_CONTEXT_LINES)))
    chosen = sorted(set(keep))[:MAX_BUILD_ERROR_LINES]
    return [lines[index] for index in chosen]
