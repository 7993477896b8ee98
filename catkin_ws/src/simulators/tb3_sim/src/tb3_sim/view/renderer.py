"""Top-down drawing of a Scene with Qt's QPainter: walls, models, the robots, their trails and the laser rays.

`paint(painter, scene, view)` draws on any QPaintDevice (the snapshot's QImage now; an interactive window's
paintEvent later), `render_image(scene, ...)` returns a QImage and `save_png(...)` writes one. No QApplication
is needed to paint on a QImage, in any thread; set QT_QPA_PLATFORM=offscreen where no display exists.
Nothing here knows about physics or ROS: the scene is a copy of the world's state.

Picture: world +x to the right, +y up; a 1 m grid, under the floor layer with its markings (if any); static
geometry in its colour (grey by default), models in theirs (by default dynamic ones brown, static ones dark brown),
robots dark blue with a yellow heading mark, trails light blue, the first robot's laser rays translucent red ending
at red hit dots. The floor, the static geometry and the models are the scene primitives (core.scene_primitives)
that every view draws, painted by view.primitive_painter.
"""

from dataclasses import dataclass
from functools import lru_cache

from PyQt5.QtCore import QLineF, QPointF, Qt
from PyQt5.QtGui import QBrush, QColor, QImage, QPainter, QPen, QPolygonF, QTransform

from tb3_sim.core.primitives import primitives_extent
from tb3_sim.core.scene_primitives import model_primitives, scene_primitives
from tb3_sim.view.primitive_painter import paint_primitives

SNAPSHOT_SIZE_PX = 800
MARGIN_M = 0.5
MIN_EXTENT_M = 4.0
GRID_SPACING_M = 1.0
WALL_WIDTH_PX = 3.0
HEADING_LENGTH_M = 0.12

BACKGROUND = QColor(250, 250, 247)
GRID = QColor(225, 225, 220)
STATIC_FILL = QColor(128, 128, 128)
MODEL_FILL = QColor(176, 120, 64)
STATIC_MODEL_FILL = QColor(110, 72, 40)
ROBOT_FILL = QColor(30, 60, 140)
HEADING = QColor(250, 210, 40)
TRAIL = QColor(120, 180, 230)
RAY = QColor(220, 40, 40, 60)
HIT = QColor(220, 40, 40)


@dataclass(frozen=True)
class View:
    """World-to-pixel mapping: `scale` px per metre, world point (`left`, `top`) at pixel (0, 0)."""

    left: float
    top: float
    scale: float
    width_px: int
    height_px: int

    @classmethod
    def fit(cls, scene, width_px=SNAPSHOT_SIZE_PX, height_px=SNAPSHOT_SIZE_PX):
        """A view showing all of the scene's geometry, robot and trail with a margin, centred, aspect kept."""
        xs, ys = _scene_extent_points(scene)
        cx, cy = (min(xs) + max(xs)) / 2.0, (min(ys) + max(ys)) / 2.0
        span_x = max(max(xs) - min(xs) + 2 * MARGIN_M, MIN_EXTENT_M)
        span_y = max(max(ys) - min(ys) + 2 * MARGIN_M, MIN_EXTENT_M)
        scale = min(width_px / span_x, height_px / span_y)
        return cls(cx - width_px / (2 * scale), cy + height_px / (2 * scale), scale, width_px, height_px)

    def to_pixel(self, x, y):
        """Pixel (column, row) as floats of the world point (x, y)."""
        return (x - self.left) * self.scale, (self.top - y) * self.scale

    def to_world(self, column, row):
        """World point (x, y) of the pixel position (column, row)."""
        return self.left + column / self.scale, self.top - row / self.scale

    def contains(self, x, y):
        """True if the world point (x, y) is inside the picture."""
        column, row = self.to_pixel(x, y)
        return 0 <= column <= self.width_px and 0 <= row <= self.height_px

    def point(self, x, y):
        return QPointF(*self.to_pixel(x, y))

    def transform(self):
        """The QTransform from world metres to this view's pixels."""
        return QTransform(self.scale, 0.0, 0.0, -self.scale, -self.left * self.scale, self.top * self.scale)


def _scene_extent_points(scene):
    xs, ys = [r.pose.x for r in scene.robots] or [0.0], [r.pose.y for r in scene.robots] or [0.0]
    extent = primitives_extent(_fixed_primitives(scene))
    if extent is not None:
        xs.extend(extent[0::2])
        ys.extend(extent[1::2])
    for model in scene.models:
        xs.append(model.pose.x)
        ys.append(model.pose.y)
    for stroke in (stroke for robot in scene.robots for stroke in robot.trail):
        xs.extend(p[0] for p in stroke)
        ys.extend(p[1] for p in stroke)
    return xs, ys


def render_image(scene, width_px=SNAPSHOT_SIZE_PX, height_px=SNAPSHOT_SIZE_PX):
    """(QImage, View) of `scene`, fitted to `width_px` x `height_px`."""
    view = View.fit(scene, width_px, height_px)
    image = QImage(width_px, height_px, QImage.Format_RGB32)
    image.fill(BACKGROUND)
    painter = QPainter(image)
    try:
        paint(painter, scene, view)
    finally:
        painter.end()
    return image, view


def save_png(scene, path, width_px=SNAPSHOT_SIZE_PX, height_px=SNAPSHOT_SIZE_PX):
    """Write `scene` as a PNG to `path`; raises OSError if the file cannot be written."""
    image, _ = render_image(scene, width_px, height_px)
    if not image.save(str(path), "PNG"):
        raise OSError(f"cannot write a PNG to {path}")


def paint(painter, scene, view):
    """Draw `scene` with `painter` through `view` (grid, floor, geometry, models, trail, rays, robot). The floor
    layer covers the grid, as the floor hides Gazebo's grid."""
    painter.setRenderHint(QPainter.Antialiasing)
    _paint_grid(painter, view)
    _paint_in_world(painter, view, _fixed_primitives(scene) + _model_primitives(scene))
    _paint_trail(painter, scene, view)
    _paint_scan(painter, scene, view)
    _paint_robots(painter, scene, view)


def _paint_grid(painter, view):
    painter.setPen(QPen(GRID, 1.0))
    x_min, y_max = view.left, view.top
    x_max, y_min = x_min + view.width_px / view.scale, y_max - view.height_px / view.scale
    x = GRID_SPACING_M * int(x_min // GRID_SPACING_M)
    while x <= x_max:
        painter.drawLine(QLineF(view.point(x, y_min), view.point(x, y_max)))
        x += GRID_SPACING_M
    y = GRID_SPACING_M * int(y_min // GRID_SPACING_M)
    while y <= y_max:
        painter.drawLine(QLineF(view.point(x_min, y), view.point(x_max, y)))
        y += GRID_SPACING_M


def _rgb(colour):
    return colour.red(), colour.green(), colour.blue()


def _fixed_primitives(scene):
    """The floor layer and the static shapes, in their colours (the view's grey by default)."""
    return list(_fixed_primitives_of(scene.floor, scene.static_shapes))


@lru_cache(maxsize=4)
def _fixed_primitives_of(floor, static_shapes):
    """Memoised: the window repaints at REPAINT_HZ, and flattening a detailed floor's curves and dashes takes
    milliseconds; the fixed scene never changes while a world runs."""
    return tuple(scene_primitives(floor, static_shapes, _rgb(STATIC_FILL)))


def _model_primitives(scene):
    parts = []
    for model in scene.models:
        rgb = model.rgb or _rgb(STATIC_MODEL_FILL if model.static else MODEL_FILL)
        parts.extend(model_primitives(model.shape, model.pose, rgb))
    return parts


def _paint_in_world(painter, view, primitives):
    painter.save()
    painter.setTransform(view.transform())
    paint_primitives(painter, primitives)
    painter.restore()


def _paint_trail(painter, scene, view):
    painter.setPen(QPen(TRAIL, 2.0))
    painter.setBrush(Qt.NoBrush)
    for stroke in (stroke for robot in scene.robots for stroke in robot.trail):
        if len(stroke) > 1:
            painter.drawPolyline(QPolygonF([view.point(x, y) for x, y in stroke]))


def _paint_scan(painter, scene, view):
    hits = scene.scan_hits()
    if not len(hits):
        return
    origin = view.point(scene.scan_origin.x, scene.scan_origin.y)
    painter.setPen(QPen(RAY, 1.0))
    for x, y in hits:
        painter.drawLine(QLineF(origin, view.point(x, y)))
    painter.setPen(Qt.NoPen)
    painter.setBrush(QBrush(HIT))
    for x, y in hits:
        painter.drawEllipse(view.point(x, y), 2.0, 2.0)


def _paint_robots(painter, scene, view):
    for robot in scene.robots:
        pose = robot.pose
        painter.setPen(Qt.NoPen)
        painter.setBrush(QBrush(ROBOT_FILL))
        for outline in robot.outlines:
            painter.drawPolygon(QPolygonF([view.point(*pose.compose(x, y)) for x, y in outline]))
        painter.setPen(QPen(HEADING, 3.0))
        painter.drawLine(QLineF(view.point(pose.x, pose.y), view.point(*pose.compose(HEADING_LENGTH_M, 0.0))))
