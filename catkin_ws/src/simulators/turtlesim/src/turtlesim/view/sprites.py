"""The project's own turtle sprites, drawn with QPainter (no image of the original is used).

A sprite is a SPRITE_SIZE_PX square ARGB32 image with a transparent background and the turtle
pointing up (head at the top), like the original's image files. There are TURTLE_IMAGE_COUNT
looks: every shell colour combined with every skin colour.
"""
import itertools

from PyQt5.QtCore import QPointF, QRectF, Qt
from PyQt5.QtGui import QColor, QImage, QPainter, QPen, QPolygonF

SPRITE_SIZE_PX = 45
"""Sprite width and height; the original's first image is 45 px high."""

SHELL_COLOURS = (
    (46, 139, 87), (107, 142, 35), (160, 82, 45), (70, 130, 180),
    (218, 165, 32), (128, 0, 128), (205, 92, 92),
)
SKIN_COLOURS = ((154, 205, 50), (222, 184, 135))
LOOKS = tuple(itertools.product(SHELL_COLOURS, SKIN_COLOURS))
"""(shell rgb, skin rgb) per look index; len(LOOKS) == TURTLE_IMAGE_COUNT."""

OUTLINE_DARKNESS = 160
"""QColor.darker() factor of outlines and shell plates."""

# Shapes in sprite pixels, centre (22.5, 22.5), head towards y = 0.
LEG_RECTS = (
    QRectF(6, 9, 10, 8), QRectF(29, 9, 10, 8),
    QRectF(6, 28, 10, 8), QRectF(29, 28, 10, 8),
)
HEAD_RECT = QRectF(16.5, 1, 12, 13)
TAIL_POINTS = (QPointF(20, 38), QPointF(25, 38), QPointF(22.5, 44))
SHELL_RECT = QRectF(9.5, 8, 26, 31)
PLATE_RECT = QRectF(15.5, 15, 14, 17)
EYE_RECTS = (QRectF(19, 4, 2.5, 2.5), QRectF(23.5, 4, 2.5, 2.5))


def draw_sprite(look_index):
    """Return the sprite QImage of look `look_index` (0 <= index < len(LOOKS))."""
    shell_rgb, skin_rgb = LOOKS[look_index]
    shell, skin = QColor(*shell_rgb), QColor(*skin_rgb)
    image = QImage(SPRITE_SIZE_PX, SPRITE_SIZE_PX, QImage.Format_ARGB32)
    image.fill(Qt.transparent)
    painter = QPainter(image)
    try:
        painter.setRenderHint(QPainter.Antialiasing)
        painter.setPen(QPen(skin.darker(OUTLINE_DARKNESS), 1))
        painter.setBrush(skin)
        for rect in LEG_RECTS:
            painter.drawEllipse(rect)
        painter.drawEllipse(HEAD_RECT)
        painter.drawPolygon(QPolygonF(list(TAIL_POINTS)))
        painter.setPen(QPen(shell.darker(OUTLINE_DARKNESS), 1.5))
        painter.setBrush(shell)
        painter.drawEllipse(SHELL_RECT)
        painter.setBrush(shell.darker(OUTLINE_DARKNESS))
        painter.drawEllipse(PLATE_RECT)
        painter.setPen(Qt.NoPen)
        painter.setBrush(Qt.black)
        for rect in EYE_RECTS:
            painter.drawEllipse(rect)
    finally:
        painter.end()
    return image
