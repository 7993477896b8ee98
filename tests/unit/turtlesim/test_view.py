"""View: sprites over the canvas, rotation, snapshots; the canvas itself stays sprite-free."""
import random

from PyQt5.QtGui import QImage

from turtlesim.core.constants import TURTLE_IMAGE_COUNT, WORLD_CENTRE
from turtlesim.core.simulation import TurtleSim
from turtlesim.core.turtle import Turtle
from turtlesim.view.scene_renderer import SceneRenderer, sprite_rotation_degrees
from turtlesim.view.sprites import LOOKS, SPRITE_SIZE_PX, draw_sprite

CENTRE_PX = 249


def differing_pixels(first, second, rows, columns):
    return [(column, row) for row in rows for column in columns
            if first.pixel(column, row) != second.pixel(column, row)]


def test_there_is_one_look_per_original_image():
    assert len(LOOKS) == TURTLE_IMAGE_COUNT
    assert len(set(LOOKS)) == TURTLE_IMAGE_COUNT


def test_sprite_is_transparent_around_and_opaque_in_the_middle():
    sprite = draw_sprite(0)
    assert sprite.width() == sprite.height() == SPRITE_SIZE_PX
    assert sprite.pixelColor(0, 0).alpha() == 0
    assert sprite.pixelColor(22, 22).alpha() == 255


def test_render_shows_sprites_over_the_canvas_but_not_on_it():
    sim = TurtleSim('/turtlesim', lambda name: None, lambda level, text: None, random.Random(1))
    before = sim.canvas.image.copy()
    view = SceneRenderer().compose(sim.canvas, [turtle for _, turtle in sim.turtles()])
    near = range(CENTRE_PX - 20, CENTRE_PX + 21)
    assert len(differing_pixels(view, before, near, near)) > 300
    far = range(0, 100)
    assert differing_pixels(view, before, far, far) == []
    assert sim.canvas.image == before


def test_sprite_head_points_along_the_heading():
    renderer = SceneRenderer()
    blank = TurtleSim('/t', lambda name: None, lambda level, text: None).canvas
    right = renderer.compose(blank, [Turtle(WORLD_CENTRE, WORLD_CENTRE, 0.0)])
    up = renderer.compose(blank, [Turtle(WORLD_CENTRE, WORLD_CENTRE, 1.5707963)])
    head_right = range(CENTRE_PX + 17, CENTRE_PX + 21)
    body_rows = range(CENTRE_PX - 3, CENTRE_PX + 4)
    assert differing_pixels(right, blank.image, body_rows, head_right)
    assert not differing_pixels(up, blank.image, body_rows, head_right)
    assert sprite_rotation_degrees(0.0) == 90.0


def test_snapshot_png_has_trail_and_sprite(tmp_path):
    sim = TurtleSim('/turtlesim', lambda name: None, lambda level, text: None, random.Random(2))
    sim.step(0.0)
    sim.teleport_absolute('turtle1', 1.0, WORLD_CENTRE, 0.0)
    sim.step(0.016)
    path = str(tmp_path / 'view.png')
    turtles = [turtle for _, turtle in sim.turtles()]
    assert SceneRenderer().save_png(sim.canvas, turtles, path)
    snapshot = QImage(path)
    assert snapshot.pixelColor(150, CENTRE_PX).getRgb()[:3] == (179, 184, 255)
    assert snapshot.pixelColor(45, CENTRE_PX).getRgb()[:3] != (69, 86, 255)
