"""The view: pen canvas plus turtle sprites, for the window and for PNG snapshots.

Rendering only reads state (Turtle.screen_position, heading, image_index); the simulation
never depends on it. Sprites are rotated by (-theta*180/PI + 90) degrees about their centre,
as the original does with its up-pointing images.
"""
from PyQt5.QtCore import QPointF, Qt
from PyQt5.QtGui import QPainter, QTransform

from turtlesim.core.constants import PI, PIXELS_PER_METRE
from turtlesim.view.sprites import draw_sprite


def sprite_rotation_degrees(theta):
    """Clockwise screen rotation in degrees of an up-pointing sprite for heading theta (rad)."""
    return -theta * 180.0 / PI + 90.0


class SceneRenderer:
    """Composes views; caches one unrotated sprite per look index it has drawn."""

    def __init__(self):
        self._sprites = {}

    def compose(self, canvas, turtles):
        """Return a new QImage: a copy of `canvas` with the sprites of `turtles` (Turtle
        objects, painted in the given order, later ones on top) centred on their positions."""
        image = canvas.image.copy()
        painter = QPainter(image)
        try:
            painter.setRenderHint(QPainter.SmoothPixmapTransform)
            for turtle in turtles:
                self._paint_turtle(painter, turtle)
        finally:
            painter.end()
        return image

    def save_png(self, canvas, turtles, path):
        """Write the composed view to `path` as PNG; return True on success."""
        return self.compose(canvas, turtles).save(path, 'PNG')

    def _paint_turtle(self, painter, turtle):
        transform = QTransform()
        transform.rotate(sprite_rotation_degrees(turtle.heading))
        rotated = self._sprite(turtle.image_index).transformed(
            transform, Qt.SmoothTransformation)
        x, y = turtle.screen_position
        painter.drawImage(QPointF(x * PIXELS_PER_METRE - 0.5 * rotated.width(),
                                  y * PIXELS_PER_METRE - 0.5 * rotated.height()), rotated)

    def _sprite(self, look_index):
        if look_index not in self._sprites:
            self._sprites[look_index] = draw_sprite(look_index)
        return self._sprites[look_index]
