"""The camera's floor texture painted with Qt: the floor's primitives through the top-down views' painter
(view.primitive_painter) onto a QImage, one pixel a texel. No QApplication is needed (text comes as outlines)."""

import numpy as np
from PyQt5.QtGui import QImage, QPainter, QTransform

from tb3_sim.core.floor_texture import FloorTexture
from tb3_sim.core.materials import SKY_RGB
from tb3_sim.view.primitive_painter import paint_primitives, qcolor


def rasterise(primitives, layout):
    """(layout.rows, layout.columns, 3) uint8 RGB of `primitives` over the background grey, texel (0, 0) at the
    layout's top-left corner."""
    image = QImage(layout.columns, layout.rows, QImage.Format_RGB888)
    image.fill(qcolor(SKY_RGB))
    left, top, scale = layout.bounds[0], layout.bounds[3], 1.0 / layout.texel_m
    painter = QPainter(image)
    try:
        painter.setRenderHint(QPainter.Antialiasing)
        painter.setTransform(QTransform(scale, 0.0, 0.0, -scale, -left * scale, top * scale))
        paint_primitives(painter, primitives)
    finally:
        painter.end()
    bits = image.constBits()
    bits.setsize(image.byteCount())
    rows = np.frombuffer(bits, dtype=np.uint8).reshape(layout.rows, image.bytesPerLine())
    return rows[:, :3 * layout.columns].reshape(layout.rows, layout.columns, 3).copy()


def floor_texture(floor):
    """The FloorTexture of the floor.Floor `floor` (about 0.5 s plus Qt's import for a detailed 8 x 8 m floor)."""
    return FloorTexture.of(floor, rasterise)
