"""Is there an X display to open a window on? (no Qt, no ROS)

Qt aborts the whole process when it cannot connect to $DISPLAY, so a program asks here
first and runs headless, with one line of guidance (window_hint.hints), when there is none.
"""
import os
import re
import socket

X11_SOCKET = '/tmp/.X11-unix/X%d'
"""Path of a local X server's Unix socket for display number N (Linux also offers it in the
abstract namespace, with a leading NUL)."""

X11_TCP_BASE_PORT = 6000
"""An X server for display N listens on TCP port 6000 + N."""

DISPLAY_PATTERN = re.compile(r'^(?P<host>[^:]*):(?P<number>\d+)(\.\d+)?$')
"""[host]:display[.screen], the usual form of $DISPLAY."""

CONNECT_TIMEOUT_S = 1.0

NO_DISPLAY = 'no display'
"""display_problem's answer when no display is set at all (the usual headless case, not a misconfiguration)."""


def x_server_address(display):
    """The (family, address) pairs to try for `display`, in order; [] when unparseable.

    Local displays (':0', 'unix:0') give the abstract and the file Unix socket; 'host:N'
    gives TCP (host, 6000 + N), resolved by socket.create_connection.
    """
    match = DISPLAY_PATTERN.match(display or '')
    if match is None:
        return []
    host, number = match.group('host'), int(match.group('number'))
    if host in ('', 'unix'):
        path = X11_SOCKET % number
        return [(socket.AF_UNIX, '\0' + path), (socket.AF_UNIX, path)]
    return [(socket.AF_INET, (host, X11_TCP_BASE_PORT + number))]


def display_reachable(display, timeout_s=CONNECT_TIMEOUT_S):
    """True when something accepts connections at the X server address of `display`."""
    for family, address in x_server_address(display):
        try:
            _connect(family, address, timeout_s)
            return True
        except OSError:
            continue
    return False


def display_problem(environ=os.environ):
    """None when a window can open (a Wayland session, or an X server answering at $DISPLAY); otherwise why not,
    in a few words for the hint line."""
    if environ.get('WAYLAND_DISPLAY'):
        return None
    display = environ.get('DISPLAY', '')
    if not display:
        return NO_DISPLAY
    if not display_reachable(display):
        return 'no display (the X server at DISPLAY=%s does not answer)' % display
    return None


def _connect(family, address, timeout_s):
    if family == socket.AF_INET:
        socket.create_connection(address, timeout_s).close()
        return
    with socket.socket(family, socket.SOCK_STREAM) as connection:
        connection.settimeout(timeout_s)
        connection.connect(address)
