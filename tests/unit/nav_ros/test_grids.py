"""nav_ros.grids: the grid messages the lab's nodes send, as a student's numpy code and the wire see them."""
import io
import math

import numpy as np
import pytest
import rospy
from nav_msgs.msg import OccupancyGrid
from nav_ros.grids import NumpyGetMapResponse, cells_of, grid_message

from lab_nav.maps.geometry import MapGeometry

CELLS = np.array([[0, 100, -1], [-1, 0, 0]], dtype=np.int8)
GEOMETRY = MapGeometry(resolution=0.05, width=3, height=2, origin_x=-1.0, origin_y=-2.0, origin_yaw=0.5)


def _wire(message):
    buffer = io.BytesIO()
    message.serialize(buffer)
    return buffer.getvalue()


def test_the_message_reshapes_back_to_the_grid_with_row_as_y():
    message = grid_message(GEOMETRY, CELLS, "map", rospy.Time(12, 5), load_time=rospy.Time(12, 5))
    assert np.array(message.data).reshape((message.info.height, message.info.width)).tolist() == CELLS.tolist()
    assert message.header.stamp == message.info.map_load_time == rospy.Time(12, 5)
    assert (message.header.frame_id, message.info.origin.position.x, message.info.origin.position.y) == (
        "map", -1.0, -2.0)
    orientation = message.info.origin.orientation
    assert 2 * math.atan2(orientation.z, orientation.w) == pytest.approx(0.5)


def test_without_a_load_time_it_stays_zero_as_gmapping_and_costmaps_leave_it():
    assert grid_message(GEOMETRY, CELLS, "map", rospy.Time(3)).info.map_load_time == rospy.Time(0)


def test_the_bytes_sent_are_those_of_the_plain_message_and_read_back_as_one():
    message = grid_message(GEOMETRY, CELLS, "map", rospy.Time(12, 5))
    plain = OccupancyGrid(header=message.header, info=message.info, data=CELLS.ravel().tolist())
    assert _wire(message) == _wire(plain)
    received = OccupancyGrid().deserialize(_wire(message))
    assert list(received.data) == CELLS.ravel().tolist()
    response = NumpyGetMapResponse(map=message)
    assert _wire(response) == _wire(plain)


def test_a_message_whose_data_does_not_fill_the_grid_is_refused():
    message = grid_message(GEOMETRY, CELLS, "map", rospy.Time(1))
    geometry, cells = cells_of(message)
    assert cells.tolist() == CELLS.tolist() and geometry == GEOMETRY
    message.data = message.data[:-1]
    with pytest.raises(ValueError, match="holds 5 values, but its info says 3 x 2 = 6 cells"):
        cells_of(message)
    assert cells_of(OccupancyGrid())[1].shape == (0, 0)
