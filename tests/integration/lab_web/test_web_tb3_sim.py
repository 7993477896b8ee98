"""The web view of tb3_sim in a real headless Chromium, against the Week 4 demo (the approach arena and its three
servers): the page draws the world where it is, follows the robot as /odom says, drives it with the arrow keys
through /cmd_vel, places and drags boxes through the /gazebo services, echoes topics and calls /move_service."""
import math
import re

import pytest
import rosgraph
import rospy
from gazebo_msgs.srv import DeleteModel, GetModelState, GetWorldProperties, SpawnModel
from geometry_msgs.msg import Point, Pose
from selenium.webdriver.common.action_chains import ActionChains
from selenium.webdriver.common.by import By
from selenium.webdriver.common.keys import Keys
from selenium.webdriver.support.ui import Select
from std_srvs.srv import Empty

from roslab import wait_for_service, wait_until
from roslab.robot_view import RobotView, pose_of

from .conftest import open_page, start_web_server

ROBOT_RGB = (0x1F, 0x4E, 0xA3)
WALL_RGB = (0x55, 0x55, 0x55)
MODEL_RGB = (0xB0, 0x78, 0x40)
FLOOR_RGB = (0xF4, 0xF4, 0xF0)
BLUE_BOX_SDF = """<?xml version="1.0"?>
<sdf version="1.6"><model name="blue_box"><static>true</static><link name="link">
  <collision name="collision"><geometry><box><size>0.2 0.2 0.3</size></box></geometry></collision>
  <visual name="visual"><geometry><box><size>0.2 0.2 0.3</size></box></geometry>
    <material><script><uri>file://media/materials/scripts/gazebo.material</uri><name>Gazebo/Blue</name></script>
    </material></visual>
</link></model></sdf>
"""


@pytest.fixture(scope="module")
def robot(ros_master):
    ros_master.roslaunch("week4_services", "week4_demo.launch", "gui:=false", "camera_width:=320",
                         "camera_height:=240")
    for name in ["/move_service", "/gazebo/reset_world", "/gazebo/spawn_sdf_model", "/gazebo/set_model_state"]:
        wait_for_service(ros_master.uri, name, timeout_s=60)
    view = RobotView(ros_master.probe())
    view.probe.subscribe("/cmd_vel", "geometry_msgs/Twist")
    return view


@pytest.fixture(scope="module")
def page(ros_master, robot, browser):
    base, _ = start_web_server(ros_master)
    open_page(browser, base, "labView.connected && labView.robot && labView.models.length === 3")
    return browser


@pytest.fixture(autouse=True)
def still_at_the_origin(robot, page):
    """Each test starts with the robot still at the origin and its trail cleared."""
    robot.probe.publish("/cmd_vel", "geometry_msgs/Twist", {})
    rospy.ServiceProxy("/gazebo/reset_world", Empty)()
    wait_until(lambda: math.hypot(*pose_of(robot.probe.wait_for_message("/odom"))[:2]) < 0.01, 10, "the reset")


def pixel(page, x, y):
    """(r, g, b) the page drew at world point (x, y)."""
    px, py = page.script("return labView.worldToPixel(arguments[0], arguments[1]);", x, y)
    return tuple(int(channel) for channel in page.canvas_pixels("world")[int(py), int(px)])


def robot_pixel(page, x, y):
    """The colour drawn on the body of a robot at (x, y) heading along +x, beside its white heading line."""
    return pixel(page, x - 0.05, y + 0.05)


def close_to(rgb, expected, tolerance=12):
    return all(abs(a - b) <= tolerance for a, b in zip(rgb, expected))


def page_robot_at(page, x, y, tolerance_m=0.01):
    shown = page.script("return labView.robot;")
    return shown is not None and math.hypot(shown["x"] - x, shown["y"] - y) <= tolerance_m


def test_the_page_draws_the_world_where_it_is_without_console_errors(page):
    assert close_to(robot_pixel(page, 0.0, 0.0), ROBOT_RGB)
    assert close_to(pixel(page, 1.0, -1.525), WALL_RGB)          # the south wall, 5 cm thick
    assert close_to(pixel(page, 1.5, 0.1), MODEL_RGB)            # target_box, 0.4 m wide at (1.5, 0)
    assert close_to(pixel(page, 0.5, 1.0), FLOOR_RGB, tolerance=20)
    assert page.driver.find_element(By.ID, "status").text == "connected"
    for navigation_only in ("tool-initial-pose", "tool-nav-goal", "cancel-goal", "save-map"):   # no amcl, move_base
        assert not page.driver.find_element(By.ID, navigation_only).is_displayed(), navigation_only
    assert page.console_errors() == []


def test_cmd_vel_from_another_node_moves_the_robot_on_the_page(robot, page):
    robot.probe.publish("/cmd_vel", "geometry_msgs/Twist", {"linear": {"x": 0.25}})
    wait_until(lambda: pose_of(robot.probe.wait_for_message("/odom"))[0] > 0.6, 20, "the robot to drive 0.6 m")
    robot.probe.publish("/cmd_vel", "geometry_msgs/Twist", {})
    x, y, _ = robot.settled_pose()
    wait_until(lambda: page_robot_at(page, x, y), 5, "the page to show the robot at /odom's pose")
    assert close_to(robot_pixel(page, x, y), ROBOT_RGB)
    assert not close_to(robot_pixel(page, 0.0, 0.0), ROBOT_RGB)   # no longer drawn at the start (0.15 m radius)
    trail = page.script("return app.trail;")
    assert trail[0] == [0.0, 0.0] and trail[-1][0] > 0.55


def test_the_up_arrow_drives_the_robot_and_releasing_it_stops_it(robot, page):
    body = page.driver.find_element(By.TAG_NAME, "body")
    robot.probe.take("/cmd_vel")
    ActionChains(page.driver).key_down(Keys.ARROW_UP, body).perform()
    try:
        robot.probe.wait_for_message("/odom", 10, lambda odom: odom["twist"]["twist"]["linear"]["x"] > 0.15)
    finally:
        ActionChains(page.driver).key_up(Keys.ARROW_UP, body).perform()
    x, y, _ = robot.settled_pose()
    assert x > 0.02 and abs(y) < 0.01
    commands = [message["msg"]["linear"]["x"] for message in robot.probe.take("/cmd_vel")]
    assert commands[-1] == 0.0 and max(commands) == pytest.approx(0.8 * 0.26)   # 80 % of the Waffle's top speed


def test_sim_time_is_the_odometrys_and_publish_point_is_stamped_in_it_without_following_clock(ros_master, robot,
                                                                                               page):
    """The server does not subscribe to /clock (100 messages a second): the page's sim time is the odometry's stamp
    and the real-time factor tb3_sim's (1x), and what a tool publishes is stamped in sim time, as RViz stamps it."""
    _, subscriptions, _ = rosgraph.Master("/test", master_uri=ros_master.uri).getSystemState()
    assert "/lab_web" not in dict(subscriptions).get("/clock", [])
    assert abs(float(page.driver.find_element(By.ID, "sim-time").text) - robot.probe.now()) < 1.0
    wait_until(lambda: abs(float(page.driver.find_element(By.ID, "rtf").text.rstrip("x")) - 1.0) <= 0.2, 10,
               "the page to show tb3_sim's real-time factor, 1x")
    robot.probe.subscribe("/clicked_point", "geometry_msgs/PointStamped")
    wait_until(lambda: page.driver.find_element(By.ID, "tool-publish-point").is_displayed(), 10, "Publish Point")
    page.driver.find_element(By.ID, "tool-publish-point").click()
    ActionChains(page.driver).move_to_element(page.driver.find_element(By.ID, "world")).click().perform()
    point = robot.probe.wait_for_message("/clicked_point", 5)
    assert point["header"]["frame_id"] == "odom"
    assert abs(point["header"]["stamp"] - robot.probe.now()) < 0.5   # sim time, not the wall's


def test_a_click_on_the_floor_spawns_a_box_dragging_moves_it_and_a_right_click_deletes_it(page):
    canvas = page.driver.find_element(By.ID, "world")
    origin = page.script("const r = arguments[0].getBoundingClientRect(); return [r.width / 2, r.height / 2];", canvas)

    def offset(x, y):
        px, py = page.script("return labView.worldToPixel(arguments[0], arguments[1]);", x, y)
        return round(px - origin[0]), round(py - origin[1])

    ActionChains(page.driver).move_to_element_with_offset(canvas, *offset(-0.5, 0.8)).click().perform()
    world = rospy.ServiceProxy("/gazebo/get_world_properties", GetWorldProperties)
    wait_until(lambda: "web_box_1" in world().model_names, 10, "get_world_properties to list web_box_1")
    state = rospy.ServiceProxy("/gazebo/get_model_state", GetModelState)
    metres_per_pixel = 1.0 / abs(offset(1.0, 0.0)[0] - offset(0.0, 0.0)[0])
    placed = state("web_box_1", "").pose.position
    assert math.hypot(placed.x + 0.5, placed.y - 0.8) <= 2 * metres_per_pixel
    wait_until(lambda: page.script("return labView.models.some(m => m.name === 'web_box_1');"), 5,
               "the page to show the box")
    (ActionChains(page.driver).move_to_element_with_offset(canvas, *offset(-0.5, 0.8)).click_and_hold()
     .move_by_offset(10, 10).move_to_element_with_offset(canvas, *offset(-0.5, -0.8)).release().perform())
    wait_until(lambda: state("web_box_1", "").pose.position.y < -0.7, 10, "set_model_state to move the box")
    moved = state("web_box_1", "").pose.position
    assert math.hypot(moved.x + 0.5, moved.y + 0.8) <= 2 * metres_per_pixel
    wait_until(lambda: page.script("return labView.models.some(m => m.name === 'web_box_1' && m.y < -0.7);"), 5,
               "the page to show the box moved")
    ActionChains(page.driver).move_to_element_with_offset(canvas, *offset(-0.5, -0.8)).context_click().perform()
    wait_until(lambda: "web_box_1" not in world().model_names, 10, "delete_model to remove web_box_1")


def test_clicking_a_topic_echoes_its_latest_message(page):
    row = page.driver.find_element(By.CSS_SELECTOR, "tr[data-topic='/odom']")
    row.click()
    wait_until(lambda: "child_frame_id: base_footprint" in page.driver.find_element(By.ID, "echo").text, 10,
               "the echo of /odom")
    row.click()
    row = page.driver.find_element(By.CSS_SELECTOR, "tr[data-topic='/odom']")
    rate = re.search(r"([\d.]+) Hz", row.text)
    assert rate and float(rate.group(1)) == pytest.approx(30.0, rel=0.3), row.text   # odom: 30 Hz of sim time


def test_the_week4_form_calls_move_service_and_shows_the_reply(page):
    Select(page.driver.find_element(By.ID, "service-name")).select_by_value("/move_service")
    wait_until(lambda: page.driver.find_elements(By.CSS_SELECTOR, "#service-fields input[name='request_signal']"),
               10, "the request's fields")
    page.driver.find_element(By.ID, "service-call").click()
    wait_until(lambda: "response_message" in page.driver.find_element(By.ID, "service-reply").text, 10, "the reply")
    assert page.driver.find_element(By.ID, "service-reply").text == (
        "response_signal: False\nresponse_message: Nothing happened: set request_signal to 'true' to move the robot.")


def lab_web_camera_topics(ros_master):
    """The camera topics lab_web subscribes to now."""
    _, subscriptions, _ = rosgraph.Master("/test", master_uri=ros_master.uri).getSystemState()
    return {topic for topic, nodes in subscriptions if "/camera/" in topic and "/lab_web" in nodes}


def thumbnail_centre(page):
    """(r, g, b) at the centre of the camera thumbnail the page shows, or None before one shows."""
    centre = page.script("""
        const image = document.getElementById('camera-img');
        if (image.hidden || !image.complete || !image.naturalWidth) return null;
        const canvas = document.createElement('canvas');
        canvas.width = image.naturalWidth;
        canvas.height = image.naturalHeight;
        const context = canvas.getContext('2d');
        context.drawImage(image, 0, 0);
        return Array.from(context.getImageData(canvas.width / 2, canvas.height / 2, 1, 1).data.slice(0, 3));""")
    return tuple(centre) if centre else None


def test_the_camera_shows_a_blue_box_ahead_in_true_colour_from_the_compressed_topic_while_asked_for(ros_master,
                                                                                                 page):
    """A Gazebo/Blue box 0.8 m ahead of the robot is blue at the thumbnail's centre (red, were the channels
    swapped); lab_web takes snapshots of the compressed images only while the page shows them."""
    assert lab_web_camera_topics(ros_master) == set()
    spawned = rospy.ServiceProxy("/gazebo/spawn_sdf_model", SpawnModel)(
        model_name="blue_box", model_xml=BLUE_BOX_SDF, initial_pose=Pose(position=Point(0.8, 0.0, 0.0)))
    assert spawned.success, spawned.status_message
    try:
        page.driver.find_element(By.ID, "camera-toggle").click()
        wait_until(lambda: thumbnail_centre(page) is not None and thumbnail_centre(page)[2] > 100, 10,
                   "a camera thumbnail of the blue box")
        wait_until(lambda: lab_web_camera_topics(ros_master) == {"/camera/rgb/image_raw/compressed"}, 5,
                   "lab_web to take a snapshot of the compressed images (the first one is raw)")
        red, green, blue = thumbnail_centre(page)
        assert blue - red >= 60 and blue - green >= 30, (red, green, blue)
    finally:
        rospy.ServiceProxy("/gazebo/delete_model", DeleteModel)(model_name="blue_box")
    page.driver.find_element(By.ID, "camera-toggle").click()
    wait_until(lambda: lab_web_camera_topics(ros_master) == set(), 5, "lab_web to unsubscribe from the camera")
    assert page.console_errors() == []

