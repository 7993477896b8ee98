"""The page as RViz's Map display and fixed frame, in a real headless Chromium: /map drawn cell by cell (unknown
grey, free white, occupied black) where its origin and resolution put it, and the robot and its LiDAR sweep placed
through map -> odom -> base_footprint. No simulator: a probe node publishes the map, the transforms, odometry and
one scan, so every pixel's place is known exactly."""
import math

import pytest

from roslab import wait_until

from .conftest import open_page, start_web_server

RESOLUTION, ORIGIN, SIZE = 0.1, (-1.0, -1.0), 40
OCCUPIED_CELL, UNKNOWN_CELL = (15, 5), (30, 30)
MAP_TO_ODOM = (1.0, 0.5, math.pi / 2)
ODOM_ROBOT = (0.5, 0.0)
SCAN_RANGE_M = 1.0
BLACK, WHITE, UNKNOWN = (0, 0, 0), (255, 255, 255), (0x70, 0x89, 0x86)
ROBOT_RGB, SCAN_RGB = (0x1F, 0x4E, 0xA3), (0xE0, 0x30, 0x30)


def quaternion(yaw):
    return {"z": math.sin(yaw / 2), "w": math.cos(yaw / 2)}


def occupancy_grid():
    cells = [0] * (SIZE * SIZE)
    for row in range(25, SIZE):
        for column in range(25, SIZE):
            cells[row * SIZE + column] = -1
    column, row = OCCUPIED_CELL
    cells[row * SIZE + column] = 100
    return {"header": {"frame_id": "map"},
            "info": {"resolution": RESOLUTION, "width": SIZE, "height": SIZE,
                     "origin": {"position": {"x": ORIGIN[0], "y": ORIGIN[1]}, "orientation": {"w": 1.0}}},
            "data": cells}


def transform(parent, child, x, y, yaw):
    return {"transforms": [{"header": {"frame_id": parent}, "child_frame_id": child, "transform": {
        "translation": {"x": x, "y": y}, "rotation": quaternion(yaw)}}]}


@pytest.fixture(scope="module")
def page(ros_master, browser):
    base, _ = start_web_server(ros_master)
    probe = ros_master.probe()
    probe.publish("/tf_static", "tf2_msgs/TFMessage", transform("base_footprint", "base_scan", 0.0, 0.0, 0.0))
    probe.publish("/odom", "nav_msgs/Odometry", {"header": {"frame_id": "odom"}, "child_frame_id": "base_footprint",
                                                 "pose": {"pose": {"position": {"x": ODOM_ROBOT[0], "y": ODOM_ROBOT[1]},
                                                                   "orientation": {"w": 1.0}}}})
    open_page(browser, base, "labView.connected && labView.robot")

    def scan_shown():
        """A scan that came before /tf_static named the LiDAR's place is not drawn: send it until one is."""
        probe.publish("/scan", "sensor_msgs/LaserScan", {"header": {"frame_id": "base_scan"}, "angle_min": 0.0,
                                                         "angle_increment": 0.1, "range_min": 0.1, "range_max": 3.5,
                                                         "ranges": [SCAN_RANGE_M]}, wait_s=1.0)
        return browser.script("return app.state.scan.length === 1;")

    wait_until(scan_shown, 10, "the page to show the scan", interval_s=0.2)
    before_the_map = browser.script("return labView.fixedFrame;")
    probe.publish("/map", "nav_msgs/OccupancyGrid", occupancy_grid())
    wait_until(lambda: browser.script("return labView.maps;") >= 1, 10, "the page to draw the map")

    def odom_placed():
        probe.publish("/tf", "tf2_msgs/TFMessage", transform("map", "odom", *MAP_TO_ODOM), wait_s=1.0)
        odom = browser.script("return app.fixed && app.fixed.odom;")
        return odom is not None and abs(odom[2] - MAP_TO_ODOM[2]) < 1e-3

    wait_until(odom_placed, 10, "the page to place odom in the map frame", interval_s=0.2)
    browser.fixed_frame_before_the_map = before_the_map
    return browser


def pixel(page, x, y):
    """(r, g, b) the page drew at fixed-frame point (x, y)."""
    px, py = page.script("return labView.worldToPixel(arguments[0], arguments[1]);", x, y)
    return tuple(int(channel) for channel in page.canvas_pixels("world")[int(py), int(px)])


def cell_centre(column, row):
    return ORIGIN[0] + (column + 0.5) * RESOLUTION, ORIGIN[1] + (row + 0.5) * RESOLUTION


def in_map(x, y):
    mx, my, yaw = MAP_TO_ODOM
    return mx + math.cos(yaw) * x - math.sin(yaw) * y, my + math.sin(yaw) * x + math.cos(yaw) * y


def close_to(rgb, expected, tolerance=12):
    return all(abs(a - b) <= tolerance for a, b in zip(rgb, expected))


def test_the_fixed_frame_is_odom_until_a_map_comes_then_map(page):
    assert page.fixed_frame_before_the_map == "odom"
    assert page.script("return labView.fixedFrame;") == "map"


def test_an_occupied_cell_is_black_free_white_unknown_grey_where_the_map_puts_them(page):
    assert pixel(page, *cell_centre(*OCCUPIED_CELL)) == BLACK
    assert pixel(page, *cell_centre(OCCUPIED_CELL[0] - 2, OCCUPIED_CELL[1])) == WHITE
    assert pixel(page, *cell_centre(*UNKNOWN_CELL)) == UNKNOWN
    assert page.console_errors() == []


def test_the_robot_and_its_scan_are_placed_through_map_odom_base_footprint(page):
    robot = in_map(*ODOM_ROBOT)                                  # (1.0, 1.0), heading +y in the map
    assert close_to(pixel(page, robot[0] + 0.05, robot[1] - 0.05), ROBOT_RGB)
    assert not close_to(pixel(page, *ODOM_ROBOT), ROBOT_RGB)     # not where odom alone would put it
    hit = in_map(ODOM_ROBOT[0] + SCAN_RANGE_M, ODOM_ROBOT[1])    # 1 m ahead: (1.0, 2.0) in the map
    assert close_to(pixel(page, *hit), SCAN_RGB)
