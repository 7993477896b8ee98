"""Paints drawing primitives (core.primitives) with Qt's QPainter: the one painter of the top-down window, the demo
PNG and the camera's floor texture (view.floor_raster). The painter's transform maps world metres to device
pixels (y flipped), so widths and sizes stay in metres; Qt antialiases by exact coverage and fills each primitive
as one path, so strokes have no seams where their pieces meet.

Text is filled from its glyph outlines (core.text_outline), never through Qt's fonts: a QImage painted without a
QGuiApplication (the simulator runs headless) cannot lay out text, and the outlines give the same letters in every
view.
"""

from PyQt5.QtCore import QPointF, QRectF, Qt
from PyQt5.QtGui import QBrush, QColor, QImage, QPainter, QPainterPath, QPen, QPolygonF

from tb3_sim.core.primitives import Disc, FilledPolygon, Image, Polyline, Text
from tb3_sim.core.text_outline import text_rings


def paint_primitives(painter, primitives):
    """Paint `primitives` in order; the painter's transform maps world metres to pixels."""
    for primitive in primitives:
        PAINTERS[type(primitive)](painter, primitive)


def qcolor(rgb):
    return QColor(*(int(c) for c in rgb))


def _polygon(points):
    return QPolygonF([QPointF(float(x), float(y)) for x, y in points])


def _fill_rings(painter, rings, rgb):
    path = QPainterPath()
    path.setFillRule(Qt.OddEvenFill)
    for ring in rings:
        path.addPolygon(_polygon(ring))
        path.closeSubpath()
    painter.setPen(Qt.NoPen)
    painter.setBrush(QBrush(qcolor(rgb)))
    painter.drawPath(path)


def _filled_polygon(painter, primitive):
    _fill_rings(painter, primitive.rings, primitive.rgb)


def _polyline(painter, primitive):
    pen = QPen(qcolor(primitive.rgb))
    pen.setWidthF(primitive.width)
    pen.setCapStyle(Qt.FlatCap)
    pen.setJoinStyle(Qt.RoundJoin)
    painter.setPen(pen)
    painter.setBrush(Qt.NoBrush)
    line = _polygon(primitive.points)
    if primitive.closed:
        painter.drawPolygon(line)
    else:
        painter.drawPolyline(line)


def _disc(painter, primitive):
    painter.setPen(Qt.NoPen)
    painter.setBrush(QBrush(qcolor(primitive.rgb)))
    painter.drawEllipse(QPointF(*primitive.center), primitive.radius, primitive.radius)


def _text(painter, primitive):
    _fill_rings(painter, text_rings(primitive), primitive.rgb)


def _image(painter, primitive):
    """The image's top row at +y: in a frame at its centre, turned by yaw and flipped so rows run down towards -y."""
    rows, columns = primitive.pixels.shape[:2]
    pixels = primitive.pixels.copy()
    image = QImage(pixels.data, columns, rows, 3 * columns, QImage.Format_RGB888)
    (sx, sy) = primitive.size
    painter.save()
    painter.translate(*primitive.center)
    painter.rotate(primitive.yaw_deg)
    painter.scale(1.0, -1.0)
    painter.setRenderHint(QPainter.SmoothPixmapTransform)
    painter.drawImage(QRectF(-sx / 2.0, -sy / 2.0, sx, sy), image)
    painter.restore()


PAINTERS = {FilledPolygon: _filled_polygon, Polyline: _polyline, Disc: _disc, Text: _text, Image: _image}
