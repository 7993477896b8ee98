"""lab_web.panels.nav.Costmap: a costmap is drawn again only when a cell or its placement changed (move_base sends the
same global patch at every update, and its costmaps whole at publish_frequency while the robot stands still)."""
from map_msgs.msg import OccupancyGridUpdate
from nav_msgs.msg import OccupancyGrid

from lab_web.panels.nav import Costmap


def grid(data, width=3, height=2, x=0.0, frame="map"):
    message = OccupancyGrid(data=list(data))
    message.header.frame_id = frame
    message.info.width, message.info.height, message.info.resolution = width, height, 0.05
    message.info.origin.position.x = x
    message.info.origin.orientation.w = 1.0
    return message


def update(x, y, width, height, data):
    return OccupancyGridUpdate(x=x, y=y, width=width, height=height, data=list(data))


def test_a_whole_grid_changes_the_picture_only_when_a_cell_its_size_origin_or_frame_differ():
    costmap = Costmap()
    assert costmap.replace(grid([0] * 6))
    assert not costmap.replace(grid([0] * 6))
    assert costmap.replace(grid([0] * 5 + [100]))
    assert costmap.replace(grid([0] * 5 + [100], x=0.05))             # the rolling window moved
    assert costmap.replace(grid([0] * 5 + [100], x=0.05, frame="odom"))
    assert costmap.replace(grid([0] * 6, width=2, height=3, x=0.05, frame="odom"))


def test_a_patch_of_the_same_cells_is_no_change_and_a_new_cost_is_written_where_it_says():
    costmap = Costmap()
    costmap.replace(grid([0] * 6))
    assert not costmap.patch(update(1, 0, 2, 2, [0] * 4))
    assert costmap.patch(update(1, 1, 2, 1, [0, 100]))
    assert costmap.cells.tolist() == [[0, 0, 0], [0, 0, 100]]
    assert not costmap.patch(update(1, 1, 2, 1, [0, 100]))


def test_a_patch_that_does_not_fit_the_grid_is_ignored():
    costmap = Costmap()
    assert not costmap.patch(update(0, 0, 1, 1, [100]))                # no grid yet
    costmap.replace(grid([0] * 6))
    assert not costmap.patch(update(2, 0, 2, 1, [100, 100]))          # past the right edge
    assert not costmap.patch(update(0, 0, 2, 1, [100]))               # data short of its size
    assert costmap.cells.tolist() == [[0, 0, 0], [0, 0, 0]]
