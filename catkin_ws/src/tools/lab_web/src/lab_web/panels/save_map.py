"""The save-map panel: "Save map" runs map_saver as a student would (`rosrun map_server map_saver -f NAME` in a
folder they name), into ~maps_home/<folder>/ (~maps_home: the student's home by default), so the map lands where
the course's pages tell them to keep it. map_saver writes the next /map it gets (gmapping and map_server latch
theirs) and exits; one that has not within SAVE_TIMEOUT_S is stopped and reported."""
import re
import subprocess
from pathlib import Path

import rospy

from lab_web import commands
from lab_web.panels.base import Panel
from lab_web.ros_context import BridgeError

SAVE_TIMEOUT_S = 30.0
PART = re.compile(r"^[A-Za-z0-9_][A-Za-z0-9_.-]{0,63}$")
"""A folder or map name: one path component, no leading dot (no hidden files, no ..)."""


def path_part(frame, key, request_id, _args):
    value = frame.get(key)
    if not isinstance(value, str) or not PART.match(value):
        raise commands.ProtocolError("{} must be a plain name (letters, digits, _ . and -, at most 64, not starting "
                                     "with a dot), got {}".format(key, str(value)[:60]), request_id)
    return value


class SaveMapPanel(Panel):
    name = "save_map"
    COMMANDS = {"save_map": commands.CommandSpec((("folder", path_part), ("name", path_part)),
                                                 "map_saver -f ~/folder/name: reply text says what was written",
                                                 "map saver")}

    def __init__(self, ros):
        super().__init__(ros)
        self._home = Path(str(rospy.get_param("~maps_home", str(Path.home())))).expanduser()

    def hello(self):
        return {"maps_home": str(self._home)}

    def handle(self, session, kind, args):
        folder = self._home / args["folder"]
        try:
            folder.mkdir(parents=True, exist_ok=True)
        except OSError as error:
            raise BridgeError("cannot make the folder {}: {}".format(folder, error.strerror or error)) from None
        try:
            done = subprocess.run(["rosrun", "map_server", "map_saver", "-f", args["name"]], cwd=str(folder),
                                  stdin=subprocess.DEVNULL, capture_output=True, text=True, timeout=SAVE_TIMEOUT_S)
        except subprocess.TimeoutExpired:
            raise BridgeError("map_saver got no map within {:g} s: is SLAM or map_server running?".format(
                SAVE_TIMEOUT_S)) from None
        if done.returncode != 0:
            lines = (done.stderr or done.stdout).strip().splitlines()
            raise BridgeError("map_saver failed: {}".format(lines[-1] if lines else "exit code {}".format(
                done.returncode)))
        return "saved {0}.pgm and {0}.yaml in {1}".format(args["name"], folder)
