"""Raw keys from a pseudo-terminal (no ROS): key mode while inside the context, the settings found before
restored on every way out, and a clear error for something that is not a terminal."""
import os
import pty
import termios

import pytest

from turtlebot3_teleop.key_terminal import KeyTerminal, NotATerminalError, key_mode

IFLAG, OFLAG, LFLAG = 0, 1, 3


@pytest.fixture
def terminal():
    """A pseudo-terminal: (the keyboard side's fd, the terminal side's fd)."""
    keyboard_fd, tty_fd = pty.openpty()
    yield keyboard_fd, tty_fd
    for fd in (keyboard_fd, tty_fd):
        try:
            os.close(fd)
        except OSError:
            pass


def test_keys_arrive_one_at_a_time_without_echo_or_signals(terminal):
    keyboard_fd, tty_fd = terminal
    before = termios.tcgetattr(tty_fd)
    with KeyTerminal(tty_fd) as keys:
        mode = termios.tcgetattr(tty_fd)
        assert not mode[LFLAG] & (termios.ICANON | termios.ECHO | termios.ISIG)
        assert mode[OFLAG] & termios.OPOST, "printed lines still start at the left margin"
        os.write(keyboard_fd, b"w\x03 ")
        assert [keys.read_key(1.0) for _ in range(3)] == ["w", "\x03", " "]
        assert keys.read_key(0.05) is None
    assert termios.tcgetattr(tty_fd) == before


def test_settings_are_restored_after_an_exception(terminal):
    _, tty_fd = terminal
    before = termios.tcgetattr(tty_fd)
    with pytest.raises(RuntimeError):
        with KeyTerminal(tty_fd):
            raise RuntimeError("boom")
    assert termios.tcgetattr(tty_fd) == before


def test_a_hung_up_terminal_ends_the_input(terminal):
    keyboard_fd, tty_fd = terminal
    with KeyTerminal(tty_fd) as keys:
        os.close(keyboard_fd)
        with pytest.raises(EOFError):
            keys.read_key(1.0)


def test_a_pipe_is_not_a_terminal():
    read_fd, write_fd = os.pipe()
    try:
        with pytest.raises(NotATerminalError, match="not a terminal"):
            KeyTerminal(read_fd)
    finally:
        os.close(read_fd)
        os.close(write_fd)


def test_key_mode_leaves_the_original_settings_alone(terminal):
    _, tty_fd = terminal
    settings = termios.tcgetattr(tty_fd)
    copy = [list(field) if isinstance(field, list) else field for field in settings]
    mode = key_mode(settings)
    assert settings == copy
    assert mode[IFLAG] & termios.ICRNL == 0 and mode[OFLAG] == settings[OFLAG]
