"""Canvas pixels: pen lines, widths, pen off, colour sensor, clear, PNG."""
from PyQt5.QtCore import Qt
from PyQt5.QtGui import QImage, QPen, qRed

from turtlesim.core.canvas import Canvas, make_qpen, world_to_screen
from turtlesim.core.constants import DT, WORLD_CENTRE
from turtlesim.core.pen import DEFAULT_PEN, Pen
from turtlesim.core.turtle import TeleportAbsolute, Turtle

BACKGROUND = (69, 86, 255)
RED = (255, 0, 0)


def horizontal_line_rows(canvas, column, y_pixel, colour):
    """Rows around y_pixel in `column` that have `colour`."""
    return [row for row in range(y_pixel - 4, y_pixel + 5)
            if canvas.color_at((column / 45.0, row / 45.0)) == colour]


def test_new_canvas_is_background_everywhere_sampled():
    canvas = Canvas()
    assert canvas.image.width() == canvas.image.height() == 500
    assert canvas.image.format() == QImage.Format_ARGB32
    for point in [(0.0, 0.0), (11.088889, 11.088889), (5.0, 3.0)]:
        assert canvas.color_at(point) == BACKGROUND


def test_color_at_uses_qt_rounding_and_clamps_to_the_image():
    canvas = Canvas()
    canvas.image.setPixel(3, 4, 0xFF010203)
    assert canvas.color_at((3.4 / 45, 4.49 / 45)) == (1, 2, 3)
    assert canvas.color_at((2.5 / 45, 3.5 / 45)) == (1, 2, 3)
    canvas.image.setPixel(499, 0, 0xFF0A0B0C)
    assert canvas.color_at((20.0, -3.0)) == (10, 11, 12)


def test_default_pen_is_qt_default_style_width_3():
    qpen = make_qpen(DEFAULT_PEN)
    assert (qpen.color().red(), qpen.color().green(), qpen.color().blue()) == (179, 184, 255)
    assert qpen.width() == 3
    assert (qpen.style(), qpen.capStyle(), qpen.joinStyle()) == (
        Qt.SolidLine, Qt.SquareCap, Qt.BevelJoin)


def test_line_then_sample_on_it_gives_the_pen_colour():
    canvas = Canvas()
    canvas.draw_line((2.0, 5.0), (4.0, 5.0), Pen(RED, 3))
    assert canvas.color_at((3.0, 5.0)) == RED
    assert horizontal_line_rows(canvas, 135, 225, RED) == [224, 225, 226]
    assert canvas.color_at((3.0, 5.2)) == BACKGROUND


def test_width_zero_still_draws_one_pixel():
    canvas = Canvas()
    qpen = make_qpen(Pen(RED, 0))
    assert qpen.width() == QPen().width() == 1
    canvas.draw_line((2.0, 5.0), (4.0, 5.0), Pen(RED, 0))
    assert horizontal_line_rows(canvas, 135, 225, RED) == [225]


def test_turtle_motion_draws_its_trail_and_senses_it_on_return():
    canvas = Canvas()
    turtle = Turtle(WORLD_CENTRE, WORLD_CENTRE, 0.0)
    turtle.set_command(1.0, 0.0, 0.0, 0.0)
    results = [turtle.update(DT, k * DT, canvas) for k in range(1, 51)]
    assert results[0].color == BACKGROUND
    assert canvas.color_at(world_to_screen(WORLD_CENTRE + 0.4, WORLD_CENTRE)) == (179, 184, 255)
    turtle.queue_teleport(TeleportAbsolute(WORLD_CENTRE + 0.4, WORLD_CENTRE, 0.0))
    assert turtle.update(DT, 100.0, canvas).color == (179, 184, 255)


def test_color_is_sampled_before_this_ticks_segment():
    canvas = Canvas()
    moving = Turtle(1.0, 1.0, 0.0)
    moving.set_command(0.5, 0.0, 0.0, 0.0)
    assert moving.update(DT, 0.0, canvas).color == BACKGROUND
    assert canvas.color_at(world_to_screen(1.0, 1.0)) == (179, 184, 255)


def test_pen_off_draws_nothing_and_keeps_colour_and_width():
    canvas = Canvas()
    turtle = Turtle(WORLD_CENTRE, WORLD_CENTRE, 0.0)
    turtle.set_pen(10, 20, 30, 5, 0)
    turtle.set_pen(99, 99, 99, 9, 1)
    assert not turtle.pen_on and turtle.pen == Pen((10, 20, 30), 5)
    turtle.set_command(2.0, 0.0, 0.0, 0.0)
    turtle.queue_teleport(TeleportAbsolute(1.0, 1.0, 0.0))
    for k in range(1, 30):
        turtle.update(DT, k * DT, canvas)
    assert canvas.image == Canvas().image


def test_teleport_draws_a_line_with_pen_on():
    canvas = Canvas()
    turtle = Turtle(2.0, 2.0, 0.0)
    turtle.queue_teleport(TeleportAbsolute(4.0, 2.0, 0.0))
    turtle.update(DT, 0.0, canvas)
    assert canvas.color_at(world_to_screen(3.0, 2.0)) == (179, 184, 255)


def test_clear_restores_the_background():
    canvas = Canvas()
    canvas.draw_line((1.0, 1.0), (5.0, 5.0), Pen(RED, 3))
    canvas.clear(BACKGROUND)
    assert canvas.image == Canvas().image
    canvas.clear((1, 2, 3))
    assert canvas.color_at((3.0, 3.0)) == (1, 2, 3)


def test_save_png_round_trips(tmp_path):
    canvas = Canvas()
    canvas.draw_line((1.0, 1.0), (5.0, 1.0), Pen(RED, 3))
    path = str(tmp_path / 'canvas.png')
    assert canvas.save_png(path)
    loaded = QImage(path)
    assert qRed(loaded.pixel(135, 45)) == 255
