"""GridMap <-> nav_msgs/OccupancyGrid (the message classes are plain data: no master needed)."""

import math

import numpy as np
from nav_msgs.msg import OccupancyGrid


def grid_message(grid, frame_id, stamp):
    """The OccupancyGrid of `grid`: header.stamp and info.map_load_time are both `stamp` (a rospy.Time), the
    origin's yaw becomes a z-rotation quaternion and z stays 0."""
    geometry = grid.geometry
    message = OccupancyGrid()
    message.header.frame_id = frame_id
    message.header.stamp = stamp
    info = message.info
    info.map_load_time = stamp
    info.resolution = geometry.resolution
    info.width, info.height = geometry.width, geometry.height
    info.origin.position.x, info.origin.position.y = geometry.origin_x, geometry.origin_y
    info.origin.orientation.z = math.sin(geometry.origin_yaw / 2.0)
    info.origin.orientation.w = math.cos(geometry.origin_yaw / 2.0)
    message.data = grid.data()
    return message


def message_cells(message):
    """int8 cells (height, width) of an OccupancyGrid; ValueError when data does not hold width x height values."""
    info = message.info
    if len(message.data) != info.width * info.height:
        raise ValueError("the map's data holds {} values, but its info says {} x {} = {} cells".format(
            len(message.data), info.width, info.height, info.width * info.height))
    return np.array(message.data, dtype=np.int8).reshape(info.height, info.width)
