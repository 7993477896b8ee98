"""GridMap <-> nav_msgs/OccupancyGrid, as a student's numpy code reads the message."""
import math

import numpy as np
import pytest
import rospy
from nav_msgs.msg import OccupancyGrid

from lab_nav.maps.geometry import MapGeometry
from lab_nav.maps.grid_map import GridMap
from map_server.messages import grid_message, message_cells

CELLS = np.array([[0, 100, -1], [-1, 0, 0]], dtype=np.int8)
GRID = GridMap(MapGeometry(resolution=0.05, width=3, height=2, origin_x=-1.0, origin_y=-2.0, origin_yaw=0.5),
               CELLS)


def test_the_message_reshapes_back_to_the_grid_with_row_as_y():
    message = grid_message(GRID, "map", rospy.Time(12, 5))
    assert np.array(message.data).reshape((message.info.height, message.info.width)).tolist() == CELLS.tolist()
    assert message.header.stamp == message.info.map_load_time == rospy.Time(12, 5)
    assert (message.header.frame_id, message.info.origin.position.x, message.info.origin.position.y) == (
        "map", -1.0, -2.0)
    orientation = message.info.origin.orientation
    assert 2 * math.atan2(orientation.z, orientation.w) == pytest.approx(0.5)


def test_a_message_whose_data_does_not_fill_the_grid_is_refused():
    message = grid_message(GRID, "map", rospy.Time(1))
    assert message_cells(message).tolist() == CELLS.tolist()
    message.data = message.data[:-1]
    with pytest.raises(ValueError, match="holds 5 values, but its info says 3 x 2 = 6 cells"):
        message_cells(message)
    assert message_cells(OccupancyGrid()).shape == (0, 0)
