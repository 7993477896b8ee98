"""Single keys from a terminal, read the way turtlebot3_teleop_key reads them (no ROS).

Input is raw while the teleop runs: no line buffering, no echo, and no signal keys, so Ctrl-C arrives as the
character '\\x03' (the teleop's quit key) instead of SIGINT. The original switches the terminal to raw mode
only around each read and back in between; here it stays in key mode for the whole run (one switch in, one
back), so a Ctrl-C never falls into a gap where it would be a signal. Output processing stays on, so printed
lines still start at the left margin. The settings found at the start are put back on leaving the context,
however it is left (normal end, exception, a signal that ends the loop).
"""
import errno
import os
import select
import termios

IFLAG, LFLAG, CC = 0, 3, 6
"""Indexes into the list termios.tcgetattr returns."""


class NotATerminalError(OSError):
    """The file descriptor is not a terminal, so there are no keys to read."""


def key_mode(settings):
    """A copy of termios `settings` for reading single keys: raw input (as tty.setraw sets it), output as it was."""
    mode = [list(field) if isinstance(field, list) else field for field in settings]
    mode[IFLAG] &= ~(termios.BRKINT | termios.ICRNL | termios.INPCK | termios.ISTRIP | termios.IXON)
    mode[LFLAG] &= ~(termios.ECHO | termios.ICANON | termios.IEXTEN | termios.ISIG)
    mode[CC][termios.VMIN] = 1
    mode[CC][termios.VTIME] = 0
    return mode


class KeyTerminal:
    """`with KeyTerminal(fd) as keys:` reads keys from terminal `fd` and restores its settings afterwards."""

    def __init__(self, fd):
        if not os.isatty(fd):
            raise NotATerminalError("file descriptor {} is not a terminal".format(fd))
        self._fd = fd
        self._saved = None

    def __enter__(self):
        self._saved = termios.tcgetattr(self._fd)
        termios.tcsetattr(self._fd, termios.TCSADRAIN, key_mode(self._saved))
        return self

    def __exit__(self, *exc_info):
        try:
            termios.tcsetattr(self._fd, termios.TCSADRAIN, self._saved)
        except termios.error as error:
            if error.args[0] != errno.EIO:
                raise
            # EIO: the terminal hung up, so there is no mode left to restore.
        return False

    def read_key(self, timeout_s):
        """The next key as a one-character str (one byte, Latin-1), or None when `timeout_s` seconds pass
        without one. Raises EOFError at the end of input or when the terminal hangs up."""
        readable, _, _ = select.select([self._fd], [], [], timeout_s)
        if not readable:
            return None
        try:
            data = os.read(self._fd, 1)
        except OSError as error:
            if error.errno != errno.EIO:
                raise
            raise EOFError("the terminal hung up") from None
        if not data:
            raise EOFError("end of input")
        return data.decode("latin-1")
