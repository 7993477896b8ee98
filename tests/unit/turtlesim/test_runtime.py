"""Runtime helpers of the nodes without ROS: headless tick timer, raw terminal."""
import os
import pty
import termios

import pytest

from turtlesim.core.ticker import run_ticks
from turtlesim.tools.terminal import NotATerminalError, RawTerminal


class FakeClock:
    """A monotonic clock that moves only when the loop waits or a tick takes time."""

    def __init__(self):
        self.now = 100.0
        self.tick_times = []

    def __call__(self):
        return self.now

    def wait(self, seconds):
        self.now += seconds
        return False


def test_ticks_keep_a_fixed_schedule_without_drift():
    clock = FakeClock()

    def tick():
        clock.tick_times.append(clock.now)
        clock.now += 0.004  # the tick itself takes 4 ms
        return len(clock.tick_times) < 100

    run_ticks(tick, clock.wait, 0.016, clock)
    assert clock.tick_times[0] == pytest.approx(100.016)
    assert clock.tick_times[-1] == pytest.approx(100.0 + 100 * 0.016)


def test_late_ticks_are_not_made_up():
    clock = FakeClock()

    def tick():
        clock.tick_times.append(clock.now)
        if len(clock.tick_times) == 2:
            clock.now += 0.1  # stalled for six intervals
        return len(clock.tick_times) < 5

    run_ticks(tick, clock.wait, 0.016, clock)
    gaps = [b - a for a, b in zip(clock.tick_times, clock.tick_times[1:])]
    assert gaps[0] == pytest.approx(0.016)
    assert gaps[1] == pytest.approx(0.1 + 0.016)
    assert gaps[2:] == pytest.approx([0.016, 0.016])


def test_a_stop_request_during_the_wait_ends_the_loop():
    ticks = []
    run_ticks(lambda: ticks.append(1) or True, lambda seconds: True, 0.016)
    assert ticks == []


@pytest.fixture
def terminal_pair():
    main_fd, tty_fd = pty.openpty()
    yield main_fd, tty_fd
    os.close(main_fd)
    os.close(tty_fd)


def test_raw_terminal_reads_single_bytes_and_restores_the_mode(terminal_pair):
    main_fd, tty_fd = terminal_pair
    cooked = termios.tcgetattr(tty_fd)
    with RawTerminal(tty_fd) as keys:
        raw = termios.tcgetattr(tty_fd)
        assert not raw[3] & (termios.ICANON | termios.ECHO)
        assert raw[3] & termios.ISIG, 'Ctrl-C must still interrupt'
        os.write(main_fd, b'\x1b[A')
        assert [keys.read_byte(1.0) for _ in range(3)] == [0x1B, ord('['), ord('A')]
        assert keys.read_byte(0.05) is None
    assert termios.tcgetattr(tty_fd) == cooked


def test_raw_terminal_restores_the_mode_after_an_error(terminal_pair):
    _, tty_fd = terminal_pair
    cooked = termios.tcgetattr(tty_fd)
    with pytest.raises(KeyboardInterrupt):
        with RawTerminal(tty_fd):
            raise KeyboardInterrupt
    assert termios.tcgetattr(tty_fd) == cooked


def test_a_hung_up_terminal_ends_the_input():
    main_fd, tty_fd = pty.openpty()
    try:
        with RawTerminal(tty_fd) as keys:
            os.close(main_fd)
            with pytest.raises(EOFError):
                keys.read_byte(1.0)
    finally:
        os.close(tty_fd)


def test_a_pipe_is_not_a_terminal():
    read_fd, write_fd = os.pipe()
    try:
        with pytest.raises(NotATerminalError, match='not a terminal'):
            RawTerminal(read_fd)
    finally:
        os.close(read_fd)
        os.close(write_fd)
