"""nav_msgs/OccupancyGrid <-> lab_nav's MapGeometry and numpy cells, and the map from the static_map service.

The grids the lab's nodes send (maps, costmaps, their responses) keep their data as a numpy array in rospy's
numpy_msg classes, which write it as one block of bytes: the plain classes pack a list value by value, ~11 ms for
a 400 x 400 map, on every map gmapping publishes and every costmap move_base does. The bytes on the wire are the
same, so subscribers get ordinary messages.
"""
import numpy as np
import rospy
from nav_msgs.msg import OccupancyGrid
from nav_msgs.srv import GetMap, GetMapResponse
from rospy.numpy_msg import numpy_msg

from lab_nav.maps.geometry import MapGeometry

from .poses import from_pose, quaternion

MAP_RETRY_S = 0.5
NumpyOccupancyGrid = numpy_msg(OccupancyGrid)
NumpyGetMapResponse = numpy_msg(GetMapResponse)


def geometry_of(info):
    """MapGeometry of a nav_msgs/MapMetaData."""
    x, y, yaw = from_pose(info.origin)
    return MapGeometry(info.resolution, info.width, info.height, x, y, yaw)


def cells_of(grid):
    """(MapGeometry, int8 (height, width) cells) of an OccupancyGrid; ValueError when the data do not fit."""
    info = grid.info
    if len(grid.data) != info.width * info.height:
        raise ValueError(f"the map's data holds {len(grid.data)} values, but its info says "
                         f"{info.width} x {info.height} = {info.width * info.height} cells")
    return geometry_of(info), np.array(grid.data, dtype=np.int8).reshape(info.height, info.width)


def grid_message(geometry, data, frame_id, stamp, load_time=None):
    """An OccupancyGrid (NumpyOccupancyGrid) of int8 data (height, width), row 0 at the origin; info.map_load_time
    is `load_time` (map_server sets it to the stamp; gmapping and costmaps leave it 0)."""
    message = NumpyOccupancyGrid()
    message.header.frame_id, message.header.stamp = frame_id, stamp
    fill_info(message.info, geometry)
    if load_time is not None:
        message.info.map_load_time = load_time
    message.data = np.ascontiguousarray(data, dtype=np.int8).ravel()
    return message


def fill_info(info, geometry):
    info.resolution = geometry.resolution
    info.width, info.height = geometry.width, geometry.height
    info.origin.position.x, info.origin.position.y = geometry.origin_x, geometry.origin_y
    info.origin.orientation = quaternion(geometry.origin_yaw)


def request_static_map(service="static_map"):
    """The map from nav_msgs/GetMap `service`, asked every MAP_RETRY_S until it answers (as amcl and
    move_base wait for map_server): INFO "Requesting the map...", WARN "Request for map failed; trying
    again..." on each failure. None if ROS shuts down first."""
    rospy.loginfo("Requesting the map...")
    get_map = rospy.ServiceProxy(service, GetMap)
    while not rospy.is_shutdown():
        try:
            return get_map().map
        except (rospy.ServiceException, rospy.ROSException):
            rospy.logwarn("Request for map failed; trying again...")
            try:
                rospy.sleep(MAP_RETRY_S)
            except rospy.ROSInterruptException:
                return None
    return None
