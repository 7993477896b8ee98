"""Raw keyboard input from a terminal, as turtle_teleop_key's original sets it up (no ROS).

The original turns off canonical mode and echo (ICANON, ECHO) so each key arrives at once and
is not printed; signals stay on, so Ctrl-C still interrupts. The previous settings are always
restored on leaving the context.
"""
import errno
import os
import select
import termios

LFLAG = 3
"""Index of c_lflag in the list termios.tcgetattr returns."""

CC = 6
"""Index of the c_cc control-character array."""


class NotATerminalError(OSError):
    """The file descriptor is not a terminal, so there are no keys to read."""


class RawTerminal:
    """`with RawTerminal(fd) as keys:` reads one byte at a time from terminal `fd`."""

    def __init__(self, fd):
        if not os.isatty(fd):
            raise NotATerminalError('file descriptor %d is not a terminal' % fd)
        self._fd = fd
        self._saved = None

    def __enter__(self):
        self._saved = termios.tcgetattr(self._fd)
        raw = termios.tcgetattr(self._fd)
        raw[LFLAG] &= ~(termios.ICANON | termios.ECHO)
        raw[CC][termios.VMIN] = 1
        raw[CC][termios.VTIME] = 0
        termios.tcsetattr(self._fd, termios.TCSANOW, raw)
        return self

    def __exit__(self, *exc_info):
        try:
            termios.tcsetattr(self._fd, termios.TCSANOW, self._saved)
        except termios.error as error:
            if error.args[0] != errno.EIO:
                raise
            # EIO: the terminal hung up, so there is no mode left to restore.
        return False

    def read_byte(self, timeout_s=None):
        """The next input byte as an int; None when `timeout_s` seconds pass without one
        (None waits for ever). Raises EOFError at the end of input or when the terminal
        hangs up (EIO, e.g. its window was closed)."""
        readable, _, _ = select.select([self._fd], [], [], timeout_s)
        if not readable:
            return None
        try:
            data = os.read(self._fd, 1)
        except OSError as error:
            if error.errno != errno.EIO:
                raise
            raise EOFError('the terminal hung up') from None
        if not data:
            raise EOFError('end of input')
        return data[0]
