"""The TurtleSim window (PyQt5 widgets; no ROS): shows composed frames, drives the tick timer.

Only used when a display is available. The simulation never depends on it: `run_window` calls
the same tick function as the headless timer, on Qt's GUI thread, every TICK_INTERVAL_MS.
"""
from PyQt5.QtCore import Qt, QTimer
from PyQt5.QtGui import QPainter
from PyQt5.QtWidgets import QApplication, QWidget

from turtlesim.core.constants import CANVAS_SIZE_PX, TICK_INTERVAL_MS, WINDOW_TITLE


class TurtleWindow(QWidget):
    """A fixed 500x500 widget titled TurtleSim that paints the last frame it was given."""

    def __init__(self):
        super().__init__()
        self.setFixedSize(CANVAS_SIZE_PX, CANVAS_SIZE_PX)
        self.setWindowTitle(WINDOW_TITLE)
        self._frame = None

    def show_frame(self, image):
        """Show `image` (a CANVAS_SIZE_PX square QImage) from the next paint on."""
        self._frame = image
        self.update()

    def paintEvent(self, event):  # noqa: N802 (Qt override)
        if self._frame is None:
            return
        painter = QPainter(self)
        try:
            painter.drawImage(0, 0, self._frame)
        finally:
            painter.end()


def run_window(tick, next_frame, argv):
    """Open the window and run Qt's event loop until `tick()` returns False or the window closes.

    Args:
        tick: callable() -> bool, called every TICK_INTERVAL_MS on the GUI thread.
        next_frame: callable() -> QImage or None, called after each tick; None keeps the
            current picture (nothing changed), so an idle simulation does not repaint.
        argv: arguments for QApplication (without ROS remappings).
    An exception raised by `tick` or `next_frame` ends the loop and is re-raised here (PyQt would
    otherwise abort the process).
    """
    app = QApplication(argv)
    window = TurtleWindow()
    timer = QTimer()
    timer.setTimerType(Qt.PreciseTimer)
    timer.setInterval(TICK_INTERVAL_MS)
    errors = []

    def on_timeout():
        try:
            if not tick():
                app.quit()
                return
            frame = next_frame()
        except Exception as error:  # handed to the caller after the loop ends
            errors.append(error)
            app.quit()
            return
        if frame is not None:
            window.show_frame(frame)

    timer.timeout.connect(on_timeout)
    window.show()
    timer.start()
    app.exec_()
    timer.stop()
    window.close()
    if errors:
        raise errors[0]
