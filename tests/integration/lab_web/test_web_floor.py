"""The web view of tb3_sim in a world with a floor layer (tests/unit/tb3_sim/fixtures/floor_worlds), in a real
headless Chromium: the page draws the floor's markings, text included, and the static shapes in their colours,
from /gazebo/scene_primitives."""
from pathlib import Path

import pytest

from roslab import wait_for_topic, wait_until

from .conftest import open_page, start_web_server

WORLD = Path(__file__).parents[2] / "unit" / "tb3_sim" / "fixtures" / "floor_worlds" / "every_marking.yaml"
MAGENTA, RED, BLUE, WHITE = (255, 0, 255), (255, 0, 0), (0, 0, 255), (255, 255, 255)


@pytest.fixture(scope="module")
def page(ros_master, browser):
    ros_master.roslaunch("tb3_sim", "tb3_sim.launch", f"world:={WORLD}", "gui:=false", "x_pos:=-1.5", "y_pos:=0.5")
    wait_for_topic(ros_master.uri, "/odom", timeout_s=60)
    base, _ = start_web_server(ros_master)
    open_page(browser, base, "labView.connected && labView.robot && labView.scenePrimitives > 0")
    return browser


def pixels(page, points):
    """(r, g, b) the page drew at each world point of `points`, from one grab of the canvas."""
    places = page.script("return arguments[0].map(p => labView.worldToPixel(p[0], p[1]));", [list(p) for p in points])
    canvas = page.canvas_pixels("world")
    return [tuple(int(channel) for channel in canvas[int(py), int(px)]) for px, py in places]


def close_to(rgb, expected, tolerance=12):
    return all(abs(a - b) <= tolerance for a, b in zip(rgb, expected))


EXPECTED = [
    ((-1.5, 0.0), MAGENTA),        # the polyline with an arrow at its start
    ((-0.75, -0.9), BLUE),         # the filled polygon
    ((0.0, 1.2), RED),             # the disc inside its black ring
    ((-2.5, 1.5), RED),            # a static pillar, in its colour
    ((0.5, 0.0), WHITE),           # the bare floor
]


def test_the_page_draws_the_floor_markings_where_they_are(page):
    drawn = pixels(page, [where for where, _ in EXPECTED])
    for (where, colour), rgb in zip(EXPECTED, drawn):
        assert close_to(rgb, colour), f"at {where} the page drew {rgb}"
    assert page.console_errors() == []


def test_the_page_draws_text_markings(page):
    """The "A" at (2.5, 1.5), 0.3 m tall: some of its box is black ink."""
    dark = pixels(page, [(2.5 + dx / 20, 1.5 + dy / 20) for dx in range(-3, 4) for dy in range(-3, 4)])
    assert sum(max(rgb) < 80 for rgb in dark) >= 5


def test_the_scene_comes_once_not_with_each_world_update(page):
    """The world frame changes while the robot's body moves (<= 2 Hz); the scene's primitives come only once."""
    frames = page.script("return labView.frames;")
    wait_until(lambda: page.script("return labView.frames;") > frames + 10, 20, "more state frames")
    assert page.script("return labView.sceneFrames;") == 1
    assert "scene" not in page.script("return app.world;")
