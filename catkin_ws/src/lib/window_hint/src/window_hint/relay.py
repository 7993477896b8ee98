"""The relay in front of Debian's window tools, started under their ROS names (redirects.txt): with a display it
becomes Debian's program with the same arguments; without one it prints the one hint line instead of Qt's or wx's
error and traceback.

Started by roslaunch (a `__name:=` argument), it then stays up until the launch stops it, keeping the node's name
and a required node's role (rviz is required in turtlebot3_slam.launch: failing would end the whole launch).
Started by rosrun or a shell, it exits 0 after the line: nothing went wrong, there is only nothing to show.
"""
import os
import signal
import sys
from pathlib import Path
from typing import NamedTuple

from window_hint.display import display_problem
from window_hint.hints import no_display_line

REDIRECTS_FILE = Path(__file__).with_name("redirects.txt")


class Redirect(NamedTuple):
    program: str    # Debian's executable
    hint: str       # key of hints.WINDOWS


def load_redirects(path=REDIRECTS_FILE):
    """{'<package>/<executable>': Redirect} from the table (also read by CMakeLists.txt to make the devel links)."""
    redirects = {}
    for line in path.read_text().splitlines():
        if line.strip() and not line.startswith("#"):
            name, program, hint = line.split()
            redirects[name] = Redirect(program, hint)
    return redirects


def ros_name(invoked_as):
    """'<package>/<executable>' from the path this was started as (devel/lib/<package>/<executable>)."""
    path = Path(invoked_as)
    return f"{path.parent.name}/{path.name}"


def started_by_roslaunch(args):
    return any(arg.startswith("__name:=") for arg in args)


def command_text(name, args):
    """What the user ran, for the xvfb-run suggestion: `rosrun <package> <executable> args` without roslaunch's
    __name/__log arguments."""
    package, executable = name.split("/")
    shown = [arg for arg in args if not arg.startswith(("__name:=", "__log:="))]
    return " ".join(["rosrun", package, executable, *shown])


def wait_for_stop():
    """Sleep until SIGINT or SIGTERM (roslaunch's stop), then return."""
    signal.signal(signal.SIGTERM, lambda *_: sys.exit(0))
    try:
        signal.pause()
    except KeyboardInterrupt:
        pass


def run(program, args, hint, command, environ=os.environ):
    """Become `program args` when a window can open; else print the hint line (and, under roslaunch, wait to be
    stopped). Returns the exit status when it does not exec."""
    problem = display_problem(environ)
    if problem is None:
        os.execv(program, [program, *args])
    print(no_display_line(hint, problem, command), file=sys.stderr, flush=True)
    if started_by_roslaunch(args):
        wait_for_stop()
    return 0


def main(argv):
    name = ros_name(argv[0])
    redirect = load_redirects().get(name)
    if redirect is None:
        print(f"window_hint: {argv[0]} is not one of the relayed tools ({', '.join(load_redirects())})",
              file=sys.stderr)
        return 2
    return run(redirect.program, argv[1:], redirect.hint, command_text(name, argv[1:]))
