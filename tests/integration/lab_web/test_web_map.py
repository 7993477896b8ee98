"""The page as RViz's Map display, fixed frame, navigation displays and publishing tools, in a real headless
Chromium: /map drawn cell by cell (unknown grey, free white, occupied black) where its origin and resolution put it,
the robot and its LiDAR sweep placed through map -> odom -> base_footprint, a costmap cell, a plan, a particle's
arrow and amcl's covariance ellipse where they are, and drags with "2D Pose Estimate", "2D Nav Goal" and "Publish
Point" publishing what RViz would. No simulator: a probe node publishes the map, the transforms, odometry and one
scan, so every pixel's place is known exactly."""
import asyncio
import base64
import json
import math

import aiohttp
import cv2
import numpy
import pytest
from selenium.webdriver.common.action_chains import ActionChains
from selenium.webdriver.common.by import By
from selenium.webdriver.common.keys import Keys
from selenium.webdriver.support.ui import Select

from lab_web import occupancy
from roslab import wait_until
from roslab.waiting import WaitTimeout

from .conftest import open_page, start_web_server

RESOLUTION, ORIGIN, SIZE = 0.1, (-1.0, -1.0), 40
OCCUPIED_CELL, UNKNOWN_CELL = (15, 5), (30, 30)
MAP_TO_ODOM = (1.0, 0.5, math.pi / 2)
ODOM_ROBOT = (0.5, 0.0)
SECOND_ROBOT = (-0.3, 0.7)
SCAN_RANGE_M = 1.0
BLACK, WHITE, UNKNOWN = (0, 0, 0), (255, 255, 255), (0x70, 0x89, 0x86)
ROBOT_RGB, SCAN_RGB = (0x1F, 0x4E, 0xA3), (0xE0, 0x30, 0x30)
TOOL_TOPICS = {"/initialpose": "geometry_msgs/PoseWithCovarianceStamped",
               "/move_base_simple/goal": "geometry_msgs/PoseStamped", "/clicked_point": "geometry_msgs/PointStamped",
               "/move_base/cancel": "actionlib_msgs/GoalID"}
RVIZ_COVARIANCE = {0: 0.25, 7: 0.25, 35: 0.06853891945200942}


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


def odometry(x, y, prefix=""):
    """A robot at (x, y) facing +x in its odom frame (`prefix`: multi_turtlebot3's tf_prefix, "tb3_1/")."""
    return {"header": {"frame_id": prefix + "odom"}, "child_frame_id": prefix + "base_footprint",
            "pose": {"pose": {"position": {"x": x, "y": y}, "orientation": {"w": 1.0}}}}


def transform(parent, child, x, y, yaw):
    return {"transforms": [{"header": {"frame_id": parent}, "child_frame_id": child, "transform": {
        "translation": {"x": x, "y": y}, "rotation": quaternion(yaw)}}]}


def show_scan(browser, probe):
    """A scan that came before /tf_static named the LiDAR's place is not drawn: send it until one is."""
    def scan_shown():
        probe.publish("/scan", "sensor_msgs/LaserScan", {"header": {"frame_id": "base_scan"}, "angle_min": 0.0,
                                                         "angle_increment": 0.1, "range_min": 0.1, "range_max": 3.5,
                                                         "ranges": [SCAN_RANGE_M]}, wait_s=1.0)
        return browser.script("return !!app.state && app.state.scan.length === 1;")

    wait_until(scan_shown, 10, "the page to show the scan", interval_s=0.2)


@pytest.fixture(scope="module")
def maps_home(tmp_path_factory):
    return tmp_path_factory.mktemp("home")


@pytest.fixture(scope="module")
def page(ros_master, browser, maps_home):
    base, _ = start_web_server(ros_master, "_maps_home:={}".format(maps_home))
    probe = ros_master.probe()
    probe.publish("/tf_static", "tf2_msgs/TFMessage", transform("base_footprint", "base_scan", 0.0, 0.0, 0.0))
    probe.publish("/odom", "nav_msgs/Odometry", odometry(*ODOM_ROBOT))
    open_page(browser, base, "labView.connected && labView.robot")

    show_scan(browser, probe)
    before_the_map = browser.script("return labView.fixedFrame;")
    probe.publish("/map", "nav_msgs/OccupancyGrid", occupancy_grid())
    wait_until(lambda: browser.script("return labView.maps;") >= 1, 10, "the page to draw the map")

    def odom_placed():
        probe.publish("/tf", "tf2_msgs/TFMessage", transform("map", "odom", *MAP_TO_ODOM), wait_s=1.0)
        odom = browser.script("return app.fixed && app.fixed.odom;")
        return odom is not None and abs(odom[2] - MAP_TO_ODOM[2]) < 1e-3

    wait_until(odom_placed, 10, "the page to place odom in the map frame", interval_s=0.2)
    browser.fixed_frame_before_the_map = before_the_map
    browser.base = base
    browser.probe = probe
    for topic, kind in TOOL_TOPICS.items():
        probe.subscribe(topic, kind)
    return browser


def pixel(page, x, y):
    """(r, g, b) the page drew at fixed-frame point (x, y)."""
    px, py = page.script("return labView.worldToPixel(arguments[0], arguments[1]);", x, y)
    return tuple(int(channel) for channel in page.canvas_pixels("world")[int(py), int(px)])


def pixel_once_drawn(page, x, y, expected, tolerance=0, timeout_s=5.0):
    """pixel(page, x, y) once it is within `tolerance` of `expected`, or what it is after `timeout_s`: the page paints
    a new state at its next animation frame, which a busy machine delays after the state itself has arrived."""
    def drawn():
        rgb = pixel(page, x, y)
        return rgb if close_to(rgb, expected, tolerance) else None
    try:
        return wait_until(drawn, timeout_s, "the page to paint", interval_s=0.1)
    except WaitTimeout:
        return pixel(page, x, y)


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


async def first_frame(base):
    async with aiohttp.ClientSession() as session:
        async with session.ws_connect(base.replace("http", "ws") + "ws") as socket:
            return json.loads((await socket.receive(timeout=10)).data)


def test_a_page_opened_once_a_map_exists_starts_in_the_map_frame(page):
    hello = asyncio.run(first_frame(page.base))
    assert hello["type"] == "hello" and hello["world_frame"] == "map", hello


def test_an_occupied_cell_is_black_free_white_unknown_grey_where_the_map_puts_them(page):
    assert pixel_once_drawn(page, *cell_centre(*OCCUPIED_CELL), BLACK) == BLACK
    assert pixel(page, *cell_centre(OCCUPIED_CELL[0] - 2, OCCUPIED_CELL[1])) == WHITE
    assert pixel(page, *cell_centre(*UNKNOWN_CELL)) == UNKNOWN
    assert page.console_errors() == []


def test_the_robot_and_its_scan_are_placed_through_map_odom_base_footprint(page):
    robot = in_map(*ODOM_ROBOT)                                  # (1.0, 1.0), heading +y in the map
    assert close_to(pixel_once_drawn(page, robot[0] + 0.05, robot[1] - 0.05, ROBOT_RGB, 12), ROBOT_RGB)
    assert not close_to(pixel(page, *ODOM_ROBOT), ROBOT_RGB)     # not where odom alone would put it
    hit = in_map(ODOM_ROBOT[0] + SCAN_RANGE_M, ODOM_ROBOT[1])    # 1 m ahead: (1.0, 2.0) in the map
    assert close_to(pixel(page, *hit), SCAN_RGB)


def drag(page, tool, start, end=None):
    """Pick `tool` (a button id) and drag on the top view from fixed-frame point `start` to `end` (a click
    without `end`); returns the canvas's metres per pixel."""
    canvas = page.driver.find_element(By.ID, "world")
    middle = page.script("const r = arguments[0].getBoundingClientRect(); return [r.width / 2, r.height / 2];",
                         canvas)

    def offset(x, y):
        px, py = page.script("return labView.worldToPixel(arguments[0], arguments[1]);", x, y)
        return round(px - middle[0]), round(py - middle[1])

    wait_until(lambda: page.driver.find_element(By.ID, tool).is_displayed(), 10,
               "the tool to show (the probe subscribes to its topic)")
    page.driver.find_element(By.ID, tool).click()
    actions = ActionChains(page.driver).move_to_element_with_offset(canvas, *offset(*start)).click_and_hold()
    if end is not None:
        actions = actions.move_by_offset(5, 5).move_to_element_with_offset(canvas, *offset(*end))
    actions.release().perform()
    return 1.0 / abs(offset(1.0, 0.0)[0] - offset(0.0, 0.0)[0])


def one_message(page, topic):
    return page.probe.wait_for_message(topic, 5)


def yaw_of(orientation):
    return 2.0 * math.atan2(orientation["z"], orientation["w"])


def test_2d_pose_estimate_publishes_initialpose_as_rviz_does(page):
    page.probe.take("/initialpose")
    metres_per_pixel = drag(page, "tool-initial-pose", (0.5, 0.0), (0.5, 1.0))
    message = one_message(page, "/initialpose")
    assert message["header"]["frame_id"] == "map"
    pose = message["pose"]["pose"]
    assert math.hypot(pose["position"]["x"] - 0.5, pose["position"]["y"]) <= 2 * metres_per_pixel
    assert yaw_of(pose["orientation"]) == pytest.approx(math.pi / 2, abs=0.02)
    covariance = message["pose"]["covariance"]
    assert covariance == [RVIZ_COVARIANCE.get(i, 0.0) for i in range(36)]
    assert not page.driver.find_element(By.ID, "tool-initial-pose").get_attribute("class").count("active")


def test_2d_nav_goal_publishes_the_goal_in_the_map_frame_facing_the_drag(page):
    page.probe.take("/move_base_simple/goal")
    metres_per_pixel = drag(page, "tool-nav-goal", (0.0, 0.5), (-1.0, 0.5))
    message = one_message(page, "/move_base_simple/goal")
    assert message["header"]["frame_id"] == "map"
    assert math.hypot(message["pose"]["position"]["x"], message["pose"]["position"]["y"] - 0.5) <= 2 * metres_per_pixel
    assert abs(yaw_of(message["pose"]["orientation"])) == pytest.approx(math.pi, abs=0.02)


def test_publish_point_and_cancel_goal(page):
    for topic in ("/clicked_point", "/move_base/cancel"):
        page.probe.take(topic)
    metres_per_pixel = drag(page, "tool-publish-point", (0.2, 0.3))
    point = one_message(page, "/clicked_point")
    assert point["header"]["frame_id"] == "map"
    assert math.hypot(point["point"]["x"] - 0.2, point["point"]["y"] - 0.3) <= 2 * metres_per_pixel
    wait_until(lambda: page.driver.find_element(By.ID, "cancel-goal").is_displayed(), 10, "the cancel button")
    page.driver.find_element(By.ID, "cancel-goal").click()
    assert one_message(page, "/move_base/cancel")["id"] == ""
    assert page.script("return labView.errors;") == []


PARTICLE, PLAN_Y, LETHAL_CELL_AT = (2.0, 0.5, 0.0), 2.5, (2.05, -0.85)
AMCL_POSE, AMCL_SIGMAS = (-0.5, 1.5, -math.pi / 2), (0.2, 0.1)
PARTICLE_RGB, PLAN_RGB, LETHAL_OVER_WHITE = (255, 25, 0), (0, 176, 0), (255, 77, 255)
FRONTIER_CELLS, FRONTIER_SPHERE = [(-0.5, -0.5), (-0.4, -0.5)], (2.5, 2.0)


def stamped_pose(x, y, yaw):
    return {"position": {"x": x, "y": y}, "orientation": quaternion(yaw)}


@pytest.fixture(scope="module")
def navigation(page):
    probe = page.probe
    probe.publish("/particlecloud", "geometry_msgs/PoseArray", {"header": {"frame_id": "map"},
                                                                "poses": [stamped_pose(*PARTICLE)]})
    probe.publish("/move_base/NavfnROS/plan", "nav_msgs/Path", {"header": {"frame_id": "map"}, "poses": [
        {"pose": stamped_pose(x, PLAN_Y, 0.0)} for x in (-0.5, 0.5)]})
    covariance = [0.0] * 36
    covariance[0], covariance[7] = AMCL_SIGMAS[0] ** 2, AMCL_SIGMAS[1] ** 2
    probe.publish("/amcl_pose", "geometry_msgs/PoseWithCovarianceStamped", {"header": {"frame_id": "map"}, "pose": {
        "pose": stamped_pose(*AMCL_POSE), "covariance": covariance}})
    probe.publish("/move_base/global_costmap/costmap", "nav_msgs/OccupancyGrid", {
        "header": {"frame_id": "map"}, "info": {"resolution": RESOLUTION, "width": 4, "height": 4, "origin": {
            "position": {"x": 2.0, "y": -0.9}, "orientation": {"w": 1.0}}}, "data": [100] + [0] * 15})
    marker = {"header": {"frame_id": "map"}, "ns": "frontiers", "action": 0, "pose": {"orientation": {"w": 1.0}}}
    probe.publish("/explore/frontiers", "visualization_msgs/MarkerArray", {"markers": [
        dict(marker, id=0, type=8, scale={"x": 0.1, "y": 0.1}, color={"b": 1.0, "a": 1.0},
             points=[{"x": x, "y": y} for x, y in FRONTIER_CELLS]),
        dict(marker, id=1, type=2, scale={"x": 0.3, "y": 0.3, "z": 0.3}, color={"g": 1.0, "a": 1.0},
             pose={"position": {"x": FRONTIER_SPHERE[0], "y": FRONTIER_SPHERE[1]}, "orientation": {"w": 1.0}})]})
    wait_until(lambda: page.script("return labView.costmaps >= 1 && !!labView.nav && !!labView.nav.amcl && "
                                   "!!labView.nav.particles && !!(labView.nav.plans || {}).global && "
                                   "labView.nav.frontiers.length === 2;"), 10,
               "the page to show the navigation displays")
    return page


def test_a_particle_is_an_arrow_and_a_plan_a_line_where_they_are(navigation):
    x, y, _ = PARTICLE
    assert close_to(pixel(navigation, x + 0.2, y), PARTICLE_RGB)          # along the arrow's 0.3 m shaft
    assert not close_to(pixel(navigation, x - 0.1, y), PARTICLE_RGB)      # nothing behind it
    assert close_to(pixel(navigation, 0.0, PLAN_Y), PLAN_RGB)


def test_a_lethal_costmap_cell_is_rvizs_purple_over_the_map(navigation):
    assert close_to(pixel(navigation, *LETHAL_CELL_AT), LETHAL_OVER_WHITE)
    assert pixel(navigation, LETHAL_CELL_AT[0] + 0.1, LETHAL_CELL_AT[1]) == WHITE   # a free cost: transparent


def test_the_covariance_ellipse_is_one_standard_deviation_along_each_axis(navigation):
    x, y, _ = AMCL_POSE
    sx, sy = AMCL_SIGMAS
    assert pixel(navigation, x + 0.8 * sx, y) != WHITE and pixel(navigation, x + 1.25 * sx, y) == WHITE
    assert pixel(navigation, x, y + 0.8 * sy) != WHITE and pixel(navigation, x, y + 1.4 * sy) == WHITE
    assert page_errors(navigation) == []


def page_errors(page):
    return page.script("return labView.errors;") + page.console_errors()


def test_save_map_runs_map_saver_into_the_folder_named_under_home(page, maps_home):
    for field, value in (("map-folder", "course_maps"), ("map-name", "arena")):
        box = page.driver.find_element(By.ID, field)
        box.clear()
        box.send_keys(value)
    page.driver.find_element(By.ID, "save-map-button").click()

    def saved():
        """map_saver takes the next /map: the probe's is not latched as gmapping's is, so send it again."""
        page.probe.publish("/map", "nav_msgs/OccupancyGrid", occupancy_grid(), wait_s=0.5)
        return "saved" in page.driver.find_element(By.ID, "save-map-reply").text

    wait_until(saved, 30, "map_saver to save the map", interval_s=0.5)
    assert (maps_home / "course_maps" / "arena.pgm").read_bytes().startswith(b"P5")
    assert "resolution: 0.1" in (maps_home / "course_maps" / "arena.yaml").read_text()


def test_explore_frontiers_are_drawn_as_their_markers_say(navigation):
    assert pixel(navigation, *FRONTIER_CELLS[0]) == (0, 0, 255)
    assert pixel(navigation, *FRONTIER_SPHERE) == (0, 255, 0)


def test_the_robot_picker_moves_the_displays_and_teleop_to_the_picked_namespace(page):
    """A second robot (multi_turtlebot3's /tb3_1) shows the picker; picking it shows its pose and the arrow key
    drives its cmd_vel; picking the global one again shows the first robot."""
    probe = page.probe
    probe.subscribe("/tb3_1/cmd_vel", "geometry_msgs/Twist")
    probe.publish("/tb3_1/odom", "nav_msgs/Odometry", odometry(*SECOND_ROBOT, "tb3_1/"), wait_s=0)   # advertised
    picker = page.driver.find_element(By.ID, "robot-pick")
    wait_until(picker.is_displayed, 10, "the robot picker (the master is read every 2 s)")
    assert page.script("return labView.robots;") == {"robots": ["/", "/tb3_1"], "picked": "/"}
    try:
        Select(picker).select_by_value("/tb3_1")
        shown_at(page, "/tb3_1/odom", odometry(*SECOND_ROBOT, "tb3_1/"), SECOND_ROBOT)
        body = page.driver.find_element(By.TAG_NAME, "body")
        ActionChains(page.driver).key_down(Keys.ARROW_UP, body).perform()
        try:
            probe.wait_for_message("/tb3_1/cmd_vel", 10, lambda twist: twist["linear"]["x"] > 0)
        finally:
            ActionChains(page.driver).key_up(Keys.ARROW_UP, body).perform()
    finally:
        Select(picker).select_by_value("/")
    show_the_global_robot_again(page)
    assert page.script("return labView.errors;") == []


def show_the_global_robot_again(page):
    """After picking "/" again, its map, map -> odom, pose and sweep as the module's fixture gave them, for the tests
    that draw them (the page keeps the picked robot's until the global topics' next messages: a /tb3_1/map still
    advertised by an earlier test is what the page drew while /tb3_1 was picked)."""
    def global_map_shown():
        page.probe.publish("/map", "nav_msgs/OccupancyGrid", occupancy_grid(), wait_s=0.5)
        page.probe.publish("/tf", "tf2_msgs/TFMessage", transform("map", "odom", *MAP_TO_ODOM), wait_s=0.5)
        odom = page.script("return labView.fixedFrame === 'map' && app.fixed.odom;")
        return bool(odom) and abs(odom[2] - MAP_TO_ODOM[2]) < 1e-3

    wait_until(global_map_shown, 20, "the page to show /map again", interval_s=0.2)
    shown_at(page, "/odom", odometry(*ODOM_ROBOT), ODOM_ROBOT)
    show_scan(page, page.probe)


def shown_at(page, topic, odom, place):
    """Publish `odom` until the page shows its robot at `place` (lab_web subscribes once the pick reaches it)."""
    def shown():
        page.probe.publish(topic, "nav_msgs/Odometry", odom, wait_s=1.0)
        robot = page.script("return labView.robot;")
        return robot is not None and math.hypot(robot["x"] - place[0], robot["y"] - place[1]) <= 0.01
    wait_until(shown, 10, "the page to show the robot of " + topic, interval_s=0.2)


MAPS_FOR_THE_HEAP, SLAM_CELLS = 20, 384
HEAP_GROWTH_LIMIT_BYTES = 1 << 20


def slam_sized_grid(step):
    """A 384 x 384 map (gmapping's for the course arenas) whose explored square grows with `step`."""
    cells = numpy.full((SLAM_CELLS, SLAM_CELLS), -1, dtype=numpy.int8)
    half = 20 + 5 * step
    low, high = SLAM_CELLS // 2 - half, SLAM_CELLS // 2 + half
    cells[low:high, low:high] = 0
    cells[low:high, [low, high - 1]] = 100
    cells[[low, high - 1], low:high] = 100
    grid = occupancy_grid()
    grid["info"].update(width=SLAM_CELLS, height=SLAM_CELLS)
    grid["data"] = cells.ravel().tolist()
    return grid


def show_map(page, grid):
    """Publish `grid` as /map and wait until the page has drawn it."""
    drawn = page.script("return labView.maps;")
    page.probe.publish("/map", "nav_msgs/OccupancyGrid", grid)
    wait_until(lambda: page.script("return labView.maps;") > drawn, 10, "the page to draw the map")


def pixels_of(base64_png):
    return cv2.imdecode(numpy.frombuffer(base64.b64decode(base64_png), numpy.uint8), cv2.IMREAD_COLOR)


def test_a_growing_slam_map_keeps_the_page_heap_flat_and_the_last_map_is_drawn_cell_for_cell(page):
    """What a mapping session does to the page, map by map (scripts/bench web_mapping_bench runs a whole session):
    20 more 384 x 384 maps leave the page's JavaScript heap within 1 MB, and the last drawn is /map's last."""
    try:
        for step in range(3):
            show_map(page, slam_sized_grid(step))
        heap_before = page.js_heap_bytes()
        for step in range(3, 3 + MAPS_FOR_THE_HEAP):
            show_map(page, slam_sized_grid(step))
        growth = page.js_heap_bytes() - heap_before
        last = slam_sized_grid(2 + MAPS_FOR_THE_HEAP)
        expected = pixels_of(occupancy.grid_png(last["data"], SLAM_CELLS, SLAM_CELLS))
        drawn = pixels_of(page.script("return labView.mapPng();").split(",", 1)[1])
        assert growth < HEAP_GROWTH_LIMIT_BYTES, growth
        assert drawn.shape == expected.shape and int(numpy.any(drawn != expected, axis=2).sum()) == 0
    finally:
        show_map(page, occupancy_grid())   # the module's own map again, for the tests that read its pixels


OWN_OCCUPIED_CELL, OWN_PARTICLE = (5, 10), (0.5, -0.5, 0.0)


def test_the_map_and_navigation_displays_follow_the_picked_robot_to_its_own_topics(page):
    """A robot with its own SLAM and amcl (/tb3_1/map in frame tb3_1/map, /tb3_1/particlecloud): picking it shows
    its map, fixed frame and particles instead of the global ones; picking the global robot shows /map again."""
    probe = page.probe
    own = occupancy_grid()
    own["header"]["frame_id"] = "tb3_1/map"
    own["data"][OCCUPIED_CELL[1] * SIZE + OCCUPIED_CELL[0]] = 0
    own["data"][OWN_OCCUPIED_CELL[1] * SIZE + OWN_OCCUPIED_CELL[0]] = 100
    cloud = {"header": {"frame_id": "tb3_1/map"}, "poses": [stamped_pose(*OWN_PARTICLE)]}
    for topic, kind, message in (("/tb3_1/odom", "nav_msgs/Odometry", odometry(*SECOND_ROBOT, "tb3_1/")),
                                 ("/tb3_1/map", "nav_msgs/OccupancyGrid", own),
                                 ("/tb3_1/particlecloud", "geometry_msgs/PoseArray", cloud)):
        probe.publish(topic, kind, message, wait_s=0)   # advertised: the server sees the robot's own topics
    picker = page.driver.find_element(By.ID, "robot-pick")
    wait_until(lambda: picker.is_displayed() and "/tb3_1" in page.script("return labView.robots.robots;"), 10,
               "the robot picker")
    try:
        Select(picker).select_by_value("/tb3_1")

        def own_displays_shown():
            probe.publish("/tb3_1/map", "nav_msgs/OccupancyGrid", own, wait_s=0.5)
            probe.publish("/tb3_1/particlecloud", "geometry_msgs/PoseArray", cloud, wait_s=0.5)
            return page.script("return labView.fixedFrame === 'tb3_1/map' && !!labView.nav && "
                               "!!labView.nav.particles && labView.nav.particles.frame === 'tb3_1/map';")

        wait_until(own_displays_shown, 20, "the page to show tb3_1's map and particles", interval_s=0.2)
        assert pixel(page, *cell_centre(*OWN_OCCUPIED_CELL)) == BLACK
        assert pixel(page, *cell_centre(*OCCUPIED_CELL)) == WHITE          # /map's occupied cell is not drawn
        x, y, _ = OWN_PARTICLE
        assert close_to(pixel(page, x + 0.2, y), PARTICLE_RGB)
        assert page_errors(page) == []
    finally:
        Select(picker).select_by_value("/")
    show_the_global_robot_again(page)
    assert pixel(page, *cell_centre(*OCCUPIED_CELL)) == BLACK
