"""The interactive top-down window (Qt): the snapshot's picture, repainted at REPAINT_HZ, plus the box tool.

Mouse: left click on the floor places a 0.3 m box; left drag moves a box or cylinder; right click deletes one
(see box_tool). The view fits the world when the window opens or is resized, and again when a robot leaves
it. The window reads the world through `scene_source()` (a Scene copied under the world lock) and edits it
through a BoxTool, so it never touches physics directly; closing it calls `on_close()`.
"""

from PyQt5.QtCore import Qt, QTimer
from PyQt5.QtGui import QPainter
from PyQt5.QtWidgets import QWidget

from tb3_sim.view.renderer import BACKGROUND, SNAPSHOT_SIZE_PX, View, paint

REPAINT_HZ = 30
WINDOW_TITLE = "tb3_sim"


class SimWindow(QWidget):
    """A QWidget showing `scene_source()`; mouse gestures go to `box_tool`; `log(text)` reports them."""

    def __init__(self, scene_source, box_tool, on_close=lambda: None, log=print):
        super().__init__()
        self._scene_source = scene_source
        self._box_tool = box_tool
        self._on_close = on_close
        self._log = log
        self._view = None
        self.setWindowTitle(WINDOW_TITLE)
        self.resize(SNAPSHOT_SIZE_PX, SNAPSHOT_SIZE_PX)
        self._timer = QTimer(self)
        self._timer.timeout.connect(self.update)
        self._timer.start(int(1000 / REPAINT_HZ))

    def view_for(self, scene):
        """The current view, refitted if the window size changed or a robot left the picture."""
        view = self._view
        if (view is None or (view.width_px, view.height_px) != (self.width(), self.height())
                or not all(view.contains(robot.pose.x, robot.pose.y) for robot in scene.robots)):
            self._view = View.fit(scene, self.width(), self.height())
        return self._view

    def paintEvent(self, _event):  # noqa: N802 (Qt's name)
        scene = self._scene_source()
        view = self.view_for(scene)
        painter = QPainter(self)
        try:
            painter.fillRect(self.rect(), BACKGROUND)
            paint(painter, scene, view)
        finally:
            painter.end()

    def _world_point(self, event):
        if self._view is None:
            self._view = View.fit(self._scene_source(), self.width(), self.height())
        return self._view.to_world(event.x(), event.y())

    def mousePressEvent(self, event):  # noqa: N802
        x, y = self._world_point(event)
        if event.button() == Qt.LeftButton:
            self._log(self._box_tool.left_press(x, y))
        elif event.button() == Qt.RightButton:
            result = self._box_tool.right_click(x, y)
            if result:
                self._log(result)

    def mouseMoveEvent(self, event):  # noqa: N802 (Qt delivers moves only while a button is held)
        self._box_tool.drag(*self._world_point(event))

    def mouseReleaseEvent(self, _event):  # noqa: N802
        self._box_tool.release()

    def closeEvent(self, event):  # noqa: N802
        self._timer.stop()
        self._on_close()
        event.accept()
