"""Screenshots of lab_web's page for the README (run through scripts/web_screenshots, from a ROS terminal).

    python3 tests/bench/web_screenshots.py [output folder, default docs/images]

Each screenshot has its own private roscore on a free port and one headless Chromium (roslab.browser), all ended
afterwards:
- lab_web_tb3_sim.png: the Week 4 demo world (week4_demo.launch, headless) with lab_web's server; the robot
  drives a short arc (trail and LiDAR dots), a box is dropped by clicking the page's floor, and /odom is
  selected in the topic list so the echo pane shows it;
- lab_web_turtlesim.png: roslaunch lab_web turtlesim_web.launch; turtle1 draws a figure eight (/turtle1/cmd_vel
  linear 2, angular +1.5 then -1.5, a few times each) so the pen trail shows;
- lab_web_navigation.png: navigation in turtlebot3_world at real time (map_server, amcl, move_base: web_bench's
  navigation_page) with the robot on its way to a goal round the pillars: the map, both costmaps, both plans,
  the particle cloud, amcl's pose and the goal as the page draws them.
All are 1400 px wide and as tall as the whole page.
"""
import sys
import tempfile
import time
from pathlib import Path

from selenium.webdriver.common.action_chains import ActionChains
from selenium.webdriver.common.by import By

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from web_bench import navigation_page  # noqa: E402

from roslab import RosMaster, free_port, http_status, wait_for_service, wait_for_topic, wait_until  # noqa: E402
from roslab.browser import HeadlessBrowser  # noqa: E402

REPO_ROOT = Path(__file__).resolve().parents[2]
WINDOW_SIZE = (1400, 1000)
"""Browser window to start with: wide enough for the two columns side by side. Before each screenshot the window
is made as tall as the page (HeadlessBrowser.save_full_page), so the echo pane and the graph below the fold show too."""
DEMO = ("week4_services", "week4_demo.launch", "gui:=false", "camera_width:=320", "camera_height:=240")
NAVIGATION_DRIVE_S = 6.0
BOX_AT = (-0.5, 0.8)
"""World point (m) where the box is dropped by a click on the page's floor."""


def say(text):
    print("web_screenshots: " + text, flush=True)




def new_browser():
    browser = HeadlessBrowser()
    browser.driver.set_window_size(*WINDOW_SIZE)
    return browser


def open_page(browser, url, ready):
    """Load `url` and wait until the page's `ready` JavaScript expression is true."""
    browser.driver.get(url)
    wait_until(lambda: browser.script("return typeof labView !== 'undefined' && !!({});".format(ready)), 30,
               "the page: " + ready)


def click_world(browser, x, y):
    """Click the page's world canvas at world point (x, y) (Selenium offsets are from the element's centre)."""
    canvas = browser.driver.find_element(By.ID, "world")
    centre = browser.script("const r = arguments[0].getBoundingClientRect(); return [r.width / 2, r.height / 2];",
                            canvas)
    px, py = browser.script("return labView.worldToPixel(arguments[0], arguments[1]);", x, y)
    ActionChains(browser.driver).move_to_element_with_offset(
        canvas, round(px - centre[0]), round(py - centre[1])).click().perform()


def select_topic(browser, topic, expected_text):
    """Click `topic` in the page's topic list and wait until its echo pane shows `expected_text`. The click is
    the page's own (JavaScript), so nothing scrolls; the topic table is then scrolled to show the row."""
    selector = "tr[data-topic='{}']".format(topic)
    wait_until(lambda: browser.driver.find_elements(By.CSS_SELECTOR, selector), 15, topic + " in the topic list")
    browser.script("arguments[0].click();", browser.driver.find_element(By.CSS_SELECTOR, selector))
    wait_until(lambda: expected_text in browser.driver.find_element(By.ID, "echo").text, 10, "the echo of " + topic)
    browser.script("const row = document.querySelector(arguments[0]); const wrap = row.closest('.table-wrap');"
                   "wrap.scrollLeft = 0; wrap.scrollTop = row.offsetTop - wrap.clientHeight / 2;", selector)


def screenshot(browser, path):
    browser.save_full_page(path)
    say("wrote {}".format(path))
    errors = browser.console_errors()
    if errors:
        say("console errors on the page: {}".format(errors))


def tb3_sim_screenshot(path):
    master = RosMaster(Path(tempfile.mkdtemp(prefix="web_screenshots_tb3_")))
    browser = None
    try:
        say("starting roscore on port {} and the Week 4 demo (tb3_sim, headless)".format(master.port))
        master.roslaunch(*DEMO)
        for service in ("/gazebo/spawn_sdf_model", "/gazebo/get_world_properties"):
            wait_for_service(master.uri, service, 60)
        wait_for_topic(master.uri, "/odom", 60)
        port = free_port()
        say("starting lab_web's server on port {}".format(port))
        server = master.rosrun("lab_web", "web_server", "_port:={}".format(port))
        url = "http://127.0.0.1:{}/".format(port)
        wait_until(lambda: http_status(url + "static/app.js") == 200 or not server.running(), 30, "lab_web")
        if not server.running():
            raise RuntimeError("lab_web's web_server exited:\n" + server.output())
        say("opening the page in headless Chromium")
        browser = new_browser()
        open_page(browser, url, "labView.connected && labView.robot && labView.models.length === 3")
        probe = master.probe()
        say("driving the robot a short arc (trail and LiDAR)")
        probe.publish("/cmd_vel", "geometry_msgs/Twist", {"linear": {"x": 0.15}, "angular": {"z": 0.35}})
        time.sleep(6.0)
        probe.publish("/cmd_vel", "geometry_msgs/Twist", {})
        say("dropping a box at ({}, {}) by clicking the page's floor".format(*BOX_AT))
        click_world(browser, *BOX_AT)
        wait_until(lambda: browser.script("return labView.models.some(m => m.name.startsWith('web_box'));"), 15,
                   "the page to show the spawned box")
        say("selecting /odom to echo it")
        select_topic(browser, "/odom", "child_frame_id")
        time.sleep(1.0)   # a few more state frames and one more graph refresh (topic rates)
        screenshot(browser, path)
    finally:
        if browser is not None:
            browser.quit()
        master.shutdown()


def turtlesim_screenshot(path):
    master = RosMaster(Path(tempfile.mkdtemp(prefix="web_screenshots_turtlesim_")))
    browser = None
    try:
        port = free_port()
        say("starting roscore on port {} and turtlesim_web.launch (page on port {})".format(master.port, port))
        master.roslaunch("lab_web", "turtlesim_web.launch", "port:={}".format(port))
        wait_for_topic(master.uri, "/turtle1/pose", 30)
        url = "http://127.0.0.1:{}/".format(port)
        wait_until(lambda: http_status(url) == 200, 30, "lab_web to serve")
        say("opening the page in headless Chromium")
        browser = new_browser()
        open_page(browser, url, "labView.connected && app.turtlesim && app.turtleImage")
        probe = master.probe()
        say("turtle1 draws a figure eight (/turtle1/cmd_vel linear 2, angular +1.5 then -1.5, 4 times each)")
        for angular in (1.5, -1.5):
            for _ in range(4):
                probe.publish("/turtle1/cmd_vel", "geometry_msgs/Twist",
                              {"linear": {"x": 2.0}, "angular": {"z": angular}})
                time.sleep(1.05)   # turtlesim drives each command for 1 s
        time.sleep(1.5)            # the last pen canvas reaches the page
        screenshot(browser, path)
    finally:
        if browser is not None:
            browser.quit()
        master.shutdown()


def navigation_screenshot(path):
    say("starting turtlebot3_world, map_server, amcl, move_base and lab_web; the robot drives to a goal")
    with navigation_page() as (browser, _probe, _pid):
        browser.driver.set_window_size(*WINDOW_SIZE)
        time.sleep(NAVIGATION_DRIVE_S)   # the robot on its way: the particles gathered, the local plan ahead
        screenshot(browser, path)


def main(argv):
    out_dir = Path(argv[1]) if len(argv) > 1 else REPO_ROOT / "docs" / "images"
    out_dir.mkdir(parents=True, exist_ok=True)
    tb3_sim_screenshot(out_dir / "lab_web_tb3_sim.png")
    turtlesim_screenshot(out_dir / "lab_web_turtlesim.png")
    navigation_screenshot(out_dir / "lab_web_navigation.png")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
