"""The one line a program prints instead of opening its window when there is no display (no ROS, no Qt).

Each window the courses open is a row of WINDOWS: what would have been started and where to see it here instead (the
browser view for the simulators, rviz and the camera; a terminal command where the browser has no such panel). The
line also names the other way, a virtual display: `xvfb-run -a <command>` (Debian's xvfb) runs the program with a
window nobody sees, which is what a tool that must have its window needs.
"""
import os
from typing import NamedTuple

from window_hint.display import NO_DISPLAY, display_problem

WEB_VIEW = "roslaunch lab_web web.launch, then open http://localhost:8080"
"""The browser view's command and address (scripts/demo --web starts it with a simulator)."""


class Window(NamedTuple):
    shows: str      # what the window would have shown, as the subject of "is not started"
    see_it: str     # how to see it here instead


WINDOWS = {
    "tb3_sim": Window("the simulator's window (Gazebo's gzclient in the course)",
                      f"{WEB_VIEW} (the world, the robot, its LiDAR; arrow keys drive)"),
    "turtlesim": Window("the TurtleSim window",
                        "roslaunch lab_web turtlesim_web.launch, then open http://localhost:8080 (a turtlesim whose "
                        "canvas the page shows)"),
    "rviz": Window("rviz", f"{WEB_VIEW} (the robot, its scan and the map)"),
    "image_view": Window("the image window", f"{WEB_VIEW} (the robot's camera), or save frames to files with "
                                             "rosrun image_view image_saver image:=TOPIC"),
    "rqt_image_view": Window("the image window", f"{WEB_VIEW} (the robot's camera)"),
    "rqt_graph": Window("the graph window", f"{WEB_VIEW} (its graph panel, live)"),
    "axclient": Window("the action client window",
                       "send a goal from a terminal: rostopic pub ACTION/goal TYPE '{goal: {...}}' and rostopic echo "
                       "ACTION/feedback"),
    "axserver": Window("the action server window", "answer goals with a node of your own (actionlib's "
                                                   "SimpleActionServer)"),
}


def no_display_line(tool, problem="no display", command=None, instead=None):
    """The single line for `tool` (a key of WINDOWS): '[tool] <problem>, so <window> is not started[; <instead>].
    See it here: ...; or in a virtual display: xvfb-run -a <command>'. `command` is what the user ran (default: the
    tool); `instead` says what the program did without its window (e.g. the file it wrote)."""
    window = WINDOWS[tool]
    done = f"; {instead}" if instead else ""
    return (f"[{tool}] {problem}, so {window.shows} is not started{done}. See it here: {window.see_it}; or in a "
            f"virtual display: xvfb-run -a {command or tool}")


def can_open_window(tool, command, info, warn, environ=os.environ):
    """True when a window can open; otherwise `tool`'s line goes to `info` (no display at all, the usual headless
    case) or to `warn` (a $DISPLAY whose X server does not answer) and the answer is False. `info` and `warn` are
    the caller's loggers (rospy.loginfo and rospy.logwarn in a node)."""
    problem = display_problem(environ)
    if problem is None:
        return True
    (info if problem == NO_DISPLAY else warn)(no_display_line(tool, problem, command))
    return False
