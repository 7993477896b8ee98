"""The pen canvas: a 500x500 ARGB32 QImage holding only pen trails, drawn as the original does.

Coordinates are screen metres (x right, y down, as the original's QPointF positions); a pixel
is metres x PIXELS_PER_METRE. Use `world_to_screen` for world coordinates. Needs no window:
QImage and QPainter work headless (QT_QPA_PLATFORM=offscreen).
"""
from PyQt5.QtCore import QBuffer, QIODevice, QPointF
from PyQt5.QtGui import QColor, QImage, QPainter, QPen, qBlue, qGreen, qRed, qRgb

from turtlesim.core.constants import CANVAS_SIZE_PX, DEFAULT_BACKGROUND, PIXELS_PER_METRE, WORLD_SIZE


def world_to_screen(x, y):
    """World metres (y up) to screen metres (y down): (x, WORLD_SIZE - y)."""
    return x, WORLD_SIZE - y


def to_pixels(point):
    """Screen metres to a QPointF in pixels (metres x 45)."""
    return QPointF(point[0] * PIXELS_PER_METRE, point[1] * PIXELS_PER_METRE)


def make_qpen(pen):
    """The QPen the original builds: QPen(QColor(r, g, b)) with Qt 5 defaults (solid line,
    square cap, bevel join, width 1), then setWidth(width) only when width is non-zero."""
    qpen = QPen(QColor(*pen.colour))
    if pen.width:
        qpen.setWidth(pen.width)
    return qpen


class Canvas:
    """The 500x500 pen canvas, filled with a background colour; turtle sprites never touch it."""

    def __init__(self, background=DEFAULT_BACKGROUND):
        """Create the image filled with `background` (r, g, b)."""
        self._image = QImage(CANVAS_SIZE_PX, CANVAS_SIZE_PX, QImage.Format_ARGB32)
        self.version = 0
        """Goes up with every change of the pixels, so a viewer re-sends the canvas only when it changed."""
        self.clear(background)

    @property
    def image(self):
        """The QImage itself (read it, do not paint on it)."""
        return self._image

    def clear(self, background):
        """Fill the whole canvas with `background` (r, g, b), erasing every trail."""
        self._image.fill(qRgb(*background))
        self.version += 1

    def draw_line(self, start, end, pen):
        """Draw a segment between two screen-metre points with a Pen, no antialiasing.

        The original calls drawLine(new_position, old_position); callers keep that order.
        """
        painter = QPainter(self._image)
        try:
            painter.setPen(make_qpen(pen))
            painter.drawLine(to_pixels(start), to_pixels(end))
        finally:
            painter.end()
        self.version += 1

    def color_at(self, point):
        """(r, g, b) of the pixel under a screen-metre point.

        The pixel is QPointF(x*45, y*45).toPoint() (Qt's qRound), as the original's color_sensor;
        it is clamped into the image, which the wall clamp already guarantees in practice.
        """
        pixel_point = to_pixels(point).toPoint()
        last = CANVAS_SIZE_PX - 1
        column = min(max(pixel_point.x(), 0), last)
        row = min(max(pixel_point.y(), 0), last)
        pixel = self._image.pixel(column, row)
        return qRed(pixel), qGreen(pixel), qBlue(pixel)

    def png_bytes(self):
        """The canvas alone, PNG-encoded in memory."""
        buffer = QBuffer()
        buffer.open(QIODevice.WriteOnly)
        self._image.save(buffer, 'PNG')
        return bytes(buffer.data())

    def save_png(self, path):
        """Write the canvas alone as a PNG file; return True on success (QImage.save)."""
        return self._image.save(path, 'PNG')
