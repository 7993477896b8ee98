"""The web view of turtlesim (roslaunch lab_web turtlesim_web.launch) in a real headless Chromium: the pen trail
turtle1 draws appears on the page's canvas, and the page's arrow keys drive turtle1."""
import pytest
from selenium.webdriver.common.action_chains import ActionChains
from selenium.webdriver.common.by import By
from selenium.webdriver.common.keys import Keys

from roslab import free_port, http_status, wait_for_topic, wait_until

from .conftest import open_page

BACKGROUND_RGB = (69, 86, 255)
PEN_RGB = (179, 184, 255)


@pytest.fixture(scope="module")
def page(ros_master, browser):
    port = free_port()
    ros_master.roslaunch("lab_web", "turtlesim_web.launch", "port:={}".format(port))
    wait_for_topic(ros_master.uri, "/turtle1/pose")
    base = "http://127.0.0.1:{}/".format(port)
    wait_until(lambda: http_status(base) == 200, 30, "lab_web to serve")
    open_page(browser, base, "labView.connected && app.turtlesim && app.turtleImage")
    return browser


def turtle_pixels_near(page, x, y):
    """The colours the page drew within a pixel of turtlesim point (x, y) (a 3 px pen line straddles it)."""
    px, py = page.script("return labView.turtleToPixel(arguments[0], arguments[1]);", x, y)
    pixels = page.canvas_pixels("turtlesim")
    return {tuple(int(channel) for channel in pixels[row, int(px)]) for row in range(int(py) - 1, int(py) + 2)}


def turtle1(page):
    return page.script("return app.turtlesim.turtles.find(t => t.name === 'turtle1');")


def test_turtle1s_pen_trail_appears_on_the_page(ros_master, page):
    start = turtle1(page)
    assert turtle_pixels_near(page, start["x"] + 1.0, start["y"]) == {BACKGROUND_RGB}
    probe = ros_master.probe()

    def moved_on_page():
        """Drive like a held key. One command is not enough: the probe's publish waits for a first subscriber,
        which may be the page's rate meter rather than turtlesim, and on a loaded machine turtlesim's 16 ms ticks
        come late, so the 1 s a command lasts moves the turtle less than 2 m."""
        if turtle1(page)["x"] > start["x"] + 1.5:
            return True
        probe.publish("/turtle1/cmd_vel", "geometry_msgs/Twist", {"linear": {"x": 2.0}})
        return False

    wait_until(moved_on_page, 10, "turtle1 to move 1.5 m on the page", interval_s=0.25)
    probe.publish("/turtle1/cmd_vel", "geometry_msgs/Twist", {})
    wait_until(lambda: PEN_RGB in turtle_pixels_near(page, start["x"] + 1.0, start["y"]), 5,
               "the pen trail on the page's canvas")
    assert page.console_errors() == []


def test_the_arrow_keys_drive_turtle1(page):
    before = turtle1(page)
    body = page.driver.find_element(By.TAG_NAME, "body")
    ActionChains(page.driver).key_down(Keys.ARROW_LEFT, body).perform()
    try:
        wait_until(lambda: abs(turtle1(page)["theta"] - before["theta"]) > 0.5, 10, "turtle1 to turn")
    finally:
        ActionChains(page.driver).key_up(Keys.ARROW_LEFT, body).perform()
    assert page.driver.find_element(By.ID, "teleop-target").text == "turtle1"


def test_turtlesim_shows_no_error_and_no_tb3_only_control(page):
    """turtlesim offers no /move_service, /gazebo/reset_world or camera: the page says nothing is wrong and does
    not offer them."""
    wait_until(lambda: "not offered" in page.driver.find_element(By.ID, "service-reply").text, 10,
               "the form to say /move_service is not offered")
    assert page.driver.find_elements(By.CSS_SELECTOR, ".failed, .message") == []
    assert page.script("return labView.errors;") == []
    for tb3_only in ("reset-world", "camera-toggle", "world", "tool-nav-goal"):
        assert not page.driver.find_element(By.ID, tb3_only).is_displayed(), tb3_only
    assert page.driver.find_element(By.ID, "turtlesim").is_displayed()
