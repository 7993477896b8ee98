"""`rosrun map_server map_server MAP.yaml`: map_server's node, over lab_nav.maps.

Node name map_server_<wall nsec> when run bare (roscpp's anonymous name), the launch file's name otherwise.
Loads the map, waits for valid ROS time (under /use_sim_time, for /clock), then publishes /map and
/map_metadata once, latched, with header.stamp = map_load_time = that time. The services are advertised just
before that first publication, as map_server does, so a caller (amcl asks /static_map) never gets an empty map.
/static_map (nav_msgs/GetMap) answers the map and logs "Sending map"; /change_map (nav_msgs/LoadMap) loads
another YAML and publishes it again, answering result 0 (SUCCESS) with the map, or 255 (UNDEFINED_FAILURE) after
logging why. ~frame_id (default "map") is the header's frame. The deprecated `map_server IMAGE RESOLUTION` form
reads ~negate (0), ~occupied_thresh (0.65) and ~free_thresh (0.196) and uses origin 0. Any error in the first map
logs map_server's own ERROR line and exits 255. Console lines are in roscpp's format, as the C++ original prints
them.

Under /use_sim_time the node follows /clock only while it needs the time: until the first map is stamped, and
while it answers a service call (nav_ros.sim_clock.ClockOnDemand; a call then takes the time of one /clock
message longer). The original keeps receiving /clock, 100 messages a sim second from the simulator, for nothing.
"""

import sys
import time

import rospy
from nav_msgs.msg import MapMetaData, OccupancyGrid
from nav_msgs.srv import GetMap, LoadMap, LoadMapResponse
from nav_ros.grids import NumpyGetMapResponse, grid_message
from nav_ros.sim_clock import ClockOnDemand
from rospy.numpy_msg import numpy_msg

from lab_nav.maps.errors import MapFileError
from lab_nav.maps.map_loader import DEPRECATED_DEFAULTS, deprecated_description, load_image_map
from lab_nav.maps.map_yaml import read_map_yaml
from map_server.command_line import EXIT_SERVER_ERROR, SERVER_DEPRECATED_WARNING, CommandLineExit, parse_server_args
from roscpp_console.handler import use_roscpp_console
from roscpp_console.line_format import error_line

VALID_TIME_POLL_S = 0.01   # wall time between looks at the clock while ROS time is still 0
NumpyLoadMapResponse = numpy_msg(LoadMapResponse)   # carries the numpy map of nav_ros.grids


def wait_for_valid_time():
    """The first non-zero ROS time (roscpp's Time::waitForValid); raises ROSInterruptException on shutdown."""
    while not rospy.is_shutdown():
        now = rospy.get_rostime()
        if not now.is_zero():
            return now
        rospy.rostime.wallsleep(VALID_TIME_POLL_S)
    raise rospy.ROSInterruptException("shut down while waiting for ROS time")


def _private_param(name, default, kind, what):
    """A ~param of `kind` (a bool is never a number here), or MapFileError "~NAME must be WHAT, got VALUE"."""
    value = rospy.get_param("~" + name, default)
    if isinstance(value, bool) or not isinstance(value, kind):
        raise MapFileError("~{} must be {}, got {!r}".format(name, what, value))
    return value


class MapServer:
    """The latched topics and the two services (advertised with the first map); `load_yaml` and
    `load_description` publish a new map."""

    def __init__(self, frame_id):
        self._frame_id = frame_id
        self._response = None
        self._services = ()
        self.clock = ClockOnDemand()
        self._metadata_pub = rospy.Publisher("map_metadata", MapMetaData, queue_size=1, latch=True)
        self._map_pub = rospy.Publisher("map", OccupancyGrid, queue_size=1, latch=True)

    def load_yaml(self, yaml_path):
        self.load_description(read_map_yaml(yaml_path))

    def load_description(self, description):
        rospy.loginfo('Loading map from image "%s"', description.image)
        grid = load_image_map(description)
        stamp = wait_for_valid_time()
        message = grid_message(grid.geometry, grid.cells, self._frame_id, stamp, load_time=stamp)
        rospy.loginfo("Read a %d X %d map @ %.3f m/cell", message.info.width, message.info.height,
                      message.info.resolution)
        self._response = NumpyGetMapResponse(map=message)
        if not self._services:
            self._services = (rospy.Service("static_map", GetMap, self._static_map),
                              rospy.Service("change_map", LoadMap, self._change_map))
        self._metadata_pub.publish(message.info)
        self._map_pub.publish(message)

    def _static_map(self, _request):
        with self.clock.running():
            rospy.loginfo("Sending map")
        return self._response

    def _change_map(self, request):
        with self.clock.running():
            return self._load_requested(request)

    def _load_requested(self, request):
        try:
            self.load_yaml(request.map_url)
        except MapFileError as error:
            rospy.logerr(str(error))
            return LoadMapResponse(result=LoadMapResponse.RESULT_UNDEFINED_FAILURE)
        rospy.loginfo("Changed map to %s", request.map_url)
        return NumpyLoadMapResponse(map=self._response.map, result=LoadMapResponse.RESULT_SUCCESS)


def _first_description(args):
    if not args.deprecated:
        return read_map_yaml(args.path)
    return deprecated_description(
        args.path, args.resolution, _private_param("negate", DEPRECATED_DEFAULTS["negate"], int, "an integer"),
        _private_param("occupied_thresh", DEPRECATED_DEFAULTS["occupied_thresh"], (int, float), "a number"),
        _private_param("free_thresh", DEPRECATED_DEFAULTS["free_thresh"], (int, float), "a number"))


def main(argv=None):
    argv = rospy.myargv(sys.argv if argv is None else argv)
    try:
        args = parse_server_args(argv[1:])
    except CommandLineExit as stop:
        error_line(stop.error)
        return stop.code
    rospy.init_node("map_server_{}".format(time.time_ns()))
    use_roscpp_console()
    if len(argv) == 3:
        rospy.logwarn(SERVER_DEPRECATED_WARNING)
    try:
        server = MapServer(_private_param("frame_id", "map", str, "a string"))
        server.load_description(_first_description(args))
        server.clock.pause()
    except MapFileError as error:
        rospy.logerr(str(error))
        return EXIT_SERVER_ERROR
    except rospy.ROSInterruptException:
        return 0
    rospy.spin()
    return 0
