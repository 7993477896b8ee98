"""`rosrun map_server map_saver [--occ N] [--free N] [-f NAME] [map:=TOPIC]`: map_saver's node, over lab_nav.maps.

Node name map_saver (not anonymous: a second one replaces the first, as in the original). Subscribes to `map`
(queue 1; remap with map:=TOPIC), writes the first map it gets to NAME.pgm and NAME.yaml relative to the working
directory, logs the original's lines ("Waiting for the map", "Received a W X H map @ R m/pix", "Writing map
occupancy data to ..." twice, "Done" and a blank line) and exits 0. A file that cannot be written logs
"Couldn't save map file to PATH" and it waits for the next map, as the original does for the PGM (for the YAML
the original would crash). A map whose data does not fill width x height is refused the same way, with the
reason. It waits forever when no map comes; Ctrl-C ends it with exit code 0. Console lines are in roscpp's
format, as the C++ original prints them.
"""

import sys
import threading

import rospy
from nav_msgs.msg import OccupancyGrid
from nav_ros.grids import cells_of

from lab_nav.maps.map_saver_files import pgm_bytes, quaternion_yaw, yaml_text
from map_server.command_line import CommandLineExit, parse_saver_args
from roscpp_console.handler import use_roscpp_console
from roscpp_console.line_format import error_line

SAVED_POLL_S = 0.1   # wall time between looks at whether the map was saved or the node shut down


class MapSaver:
    """Saves the first complete map received on `map` with the options' name and thresholds."""

    def __init__(self, options):
        self._options = options
        self.saved = threading.Event()
        rospy.loginfo("Waiting for the map")
        self._subscriber = rospy.Subscriber("map", OccupancyGrid, self._on_map, queue_size=1)

    def _on_map(self, message):
        if self.saved.is_set():
            return
        info = message.info
        rospy.loginfo("Received a %d X %d map @ %.3f m/pix", info.width, info.height, info.resolution)
        try:
            _geometry, cells = cells_of(message)
        except ValueError as error:
            rospy.logerr("Couldn't save the map: %s", error)
            return
        name, options = self._options.name, self._options
        orientation = info.origin.orientation
        yaw = quaternion_yaw(orientation.x, orientation.y, orientation.z, orientation.w)
        files = ((name + ".pgm", pgm_bytes(cells, info.resolution, options.occupied, options.free)),
                 (name + ".yaml", yaml_text(name + ".pgm", info.resolution, info.origin.position.x,
                                            info.origin.position.y, yaw).encode("ascii")))
        for path, content in files:
            rospy.loginfo("Writing map occupancy data to %s", path)
            try:
                with open(path, "wb") as output:
                    output.write(content)
            except OSError:
                rospy.logerr("Couldn't save map file to %s", path)
                return
        rospy.loginfo("Done\n")
        self.saved.set()


def main(argv=None):
    argv = rospy.myargv(sys.argv if argv is None else argv)
    try:
        options = parse_saver_args(argv[1:])
    except CommandLineExit as stop:
        if stop.output is not None:
            print(stop.output)
        if stop.error is not None:
            error_line(stop.error)
        return stop.code
    rospy.init_node("map_saver")
    use_roscpp_console()
    saver = MapSaver(options)
    while not saver.saved.wait(SAVED_POLL_S) and not rospy.is_shutdown():
        pass
    return 0
