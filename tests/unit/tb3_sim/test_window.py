"""The interactive window, offscreen: it paints the scene and turns mouse clicks into box-tool gestures."""
import os

import pytest

os.environ.setdefault("QT_QPA_PLATFORM", "offscreen")

from PyQt5.QtCore import QEvent, QPoint, QPointF, Qt  # noqa: E402  (the platform must be chosen first)
from PyQt5.QtGui import QColor, QMouseEvent  # noqa: E402
from PyQt5.QtTest import QTest  # noqa: E402
from PyQt5.QtWidgets import QApplication  # noqa: E402

from tb3_sim.core.geometry import Pose2D  # noqa: E402
from tb3_sim.core.world import World  # noqa: E402
from tb3_sim.core.world_file import load_world, shipped_world_path  # noqa: E402
from tb3_sim.view.box_tool import BoxTool  # noqa: E402
from tb3_sim.view.renderer import ROBOT_FILL  # noqa: E402
from tb3_sim.view.scene import Trails, scene_of  # noqa: E402
from tb3_sim.view.window import SimWindow  # noqa: E402


@pytest.fixture(scope="module")
def app():
    return QApplication.instance() or QApplication(["test"])


@pytest.fixture
def window(app, fake_sim):
    world = World(load_world(shipped_world_path("empty")), Pose2D(0.0, 0.0, 0.0))
    closed = []
    window = SimWindow(lambda: scene_of(world, Trails()), BoxTool(fake_sim(world)), on_close=lambda: closed.append(1),
                       log=lambda text: None)
    window.resize(400, 400)
    window.show()
    QTest.qWaitForWindowExposed(window)
    window.world, window.closed = world, closed
    yield window
    window.close()


def pixel_of(window, x, y):
    view = window.view_for(scene_of(window.world, Trails()))
    column, row = view.to_pixel(x, y)
    return QPoint(int(column), int(row))


def test_it_paints_the_robot(window):
    image = window.grab().toImage()
    centre = pixel_of(window, -0.05, 0.0)
    assert QColor(image.pixel(centre)).rgb() == ROBOT_FILL.rgb()


def test_click_places_a_box_and_right_click_deletes_it(window):
    QTest.mouseClick(window, Qt.LeftButton, Qt.NoModifier, pixel_of(window, 1.0, 0.5))
    assert window.world.get_model_state("box_1").pose[:2] == pytest.approx((1.0, 0.5), abs=0.02)
    QTest.mouseClick(window, Qt.RightButton, Qt.NoModifier, pixel_of(window, 1.0, 0.5))
    assert not window.world.has_model("box_1")


def test_drag_moves_a_box(window):
    QTest.mouseClick(window, Qt.LeftButton, Qt.NoModifier, pixel_of(window, 1.0, 0.5))
    start, end = pixel_of(window, 1.0, 0.5), pixel_of(window, -1.0, -1.0)
    QTest.mousePress(window, Qt.LeftButton, Qt.NoModifier, start)
    QApplication.sendEvent(window, QMouseEvent(QEvent.MouseMove, QPointF(end), Qt.NoButton, Qt.LeftButton,
                                               Qt.NoModifier))
    QTest.mouseRelease(window, Qt.LeftButton, Qt.NoModifier, end)
    assert window.world.get_model_state("box_1").pose[:2] == pytest.approx((-1.0, -1.0), abs=0.02)


def test_closing_reports_it(window):
    window.close()
    assert window.closed == [1]
