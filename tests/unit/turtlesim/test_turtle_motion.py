"""Turtle.update: the update rule of spec 1.7 against independently computed references."""
import math

import numpy
import pytest
from PyQt5.QtCore import QPointF

from turtlesim.core.canvas import Canvas
from turtlesim.core.constants import CMD_TIMEOUT, DT, WORLD_CENTRE, WORLD_SIZE
from turtlesim.core.geometry import qt_fuzzy_equal, wrap_heading
from turtlesim.core.turtle import TeleportAbsolute, TeleportRelative, Turtle

SPEC_PI = 3.14159265


def run(turtle, canvas, start, ticks):
    """Update `ticks` times at now = start + k*DT (k = 1..ticks); return the results."""
    return [turtle.update(DT, start + k * DT, canvas) for k in range(1, ticks + 1)]


def reference_world_pose(x, y, theta, vx, vy, w, ticks):
    """Spec 1.7 c-d in world terms, written independently of Turtle."""
    for _ in range(ticks):
        theta += w * DT
        theta -= 2 * SPEC_PI * math.floor((theta + SPEC_PI) / (2 * SPEC_PI))
        x += (vx * math.cos(theta) - vy * math.sin(theta)) * DT
        y += (vx * math.sin(theta) + vy * math.cos(theta)) * DT
    return x, y, theta


@pytest.fixture
def canvas():
    return Canvas()


def test_start_pose_is_centre_and_stopped(canvas):
    result = Turtle(WORLD_CENTRE, WORLD_CENTRE, 0.0).update(DT, 100.0, canvas)
    assert result.pose.x == pytest.approx(5.544444561004639, abs=1e-9)
    assert result.pose.y == pytest.approx(5.544444561004639, abs=1e-9)
    assert (result.pose.theta, result.pose.linear_velocity) == (0.0, 0.0)
    assert result.color == (69, 86, 255)
    assert result.wall_warning is None


def test_one_twist_moves_for_one_second_along_the_update_rule(canvas):
    turtle = Turtle(WORLD_CENTRE, WORLD_CENTRE, 0.0)
    start = 1000.0
    turtle.set_command(2.0, 0.0, 1.0, start)
    results = run(turtle, canvas, start, 100)
    moving_ticks = int(CMD_TIMEOUT / DT)
    assert moving_ticks == 62
    expected = reference_world_pose(WORLD_CENTRE, WORLD_CENTRE, 0.0, 2.0, 0.0, 1.0, moving_ticks)
    final = results[-1].pose
    assert (final.x, final.y, final.theta) == pytest.approx(expected, abs=1e-5)
    assert (final.x, final.y) == pytest.approx((7.2114, 6.4638), abs=1e-3)
    assert results[moving_ticks - 1].pose.linear_velocity == 2.0
    assert results[moving_ticks - 1].pose.angular_velocity == 1.0
    assert results[moving_ticks].pose.linear_velocity == 0.0
    assert results[moving_ticks].pose == results[-1].pose


def test_timeout_is_strictly_more_than_one_second_of_now(canvas):
    turtle = Turtle(WORLD_CENTRE, WORLD_CENTRE, 0.0)
    turtle.set_command(1.0, 0.0, 0.0, 10.0)
    assert turtle.update(DT, 11.0, canvas).pose.linear_velocity == 1.0
    assert turtle.update(DT, 11.0 + 1e-6, canvas).pose.linear_velocity == 0.0


def test_new_turtle_is_stopped_until_a_command(canvas):
    turtle = Turtle(WORLD_CENTRE, WORLD_CENTRE, 0.0)
    assert turtle.update(DT, 0.5, canvas).pose.linear_velocity == 0.0


def test_heading_wrap_keeps_theta_in_minus_pi_pi(canvas):
    turtle = Turtle(WORLD_CENTRE, WORLD_CENTRE, 3.1)
    turtle.set_command(0.0, 0.0, 10.0, 0.0)
    thetas = [result.pose.theta for result in run(turtle, canvas, 0.0, 60)]
    assert all(-SPEC_PI <= theta < SPEC_PI for theta in thetas)
    assert thetas[0] == pytest.approx(3.1 + 0.16 - 2 * SPEC_PI, abs=1e-6)
    assert wrap_heading(SPEC_PI) == pytest.approx(-SPEC_PI)
    assert wrap_heading(-SPEC_PI) == -SPEC_PI


def test_heading_changes_before_position(canvas):
    turtle = Turtle(WORLD_CENTRE, WORLD_CENTRE, 0.0)
    turtle.set_command(1.0, 0.0, 10.0, 0.0)
    pose = turtle.update(DT, 0.0, canvas).pose
    assert pose.y - WORLD_CENTRE == pytest.approx(math.sin(0.16) * DT, abs=1e-6)


def test_linear_y_strafes(canvas):
    turtle = Turtle(WORLD_CENTRE, WORLD_CENTRE, 0.0)
    turtle.set_command(0.0, 1.0, 0.0, 0.0)
    pose = run(turtle, canvas, 0.0, 10)[-1].pose
    assert pose.x == pytest.approx(WORLD_CENTRE, abs=1e-6)
    assert pose.y == pytest.approx(WORLD_CENTRE + 10 * DT, abs=1e-6)
    assert pose.linear_velocity == 1.0


def test_linear_velocity_is_a_magnitude_when_reversing(canvas):
    turtle = Turtle(WORLD_CENTRE, WORLD_CENTRE, 0.0)
    turtle.set_command(-1.5, 0.0, -0.5, 0.0)
    pose = turtle.update(DT, 0.0, canvas).pose
    assert pose.linear_velocity == 1.5
    assert pose.angular_velocity == -0.5
    assert pose.x < WORLD_CENTRE


def test_wall_clamps_and_warns_with_screen_space_y(canvas):
    turtle = Turtle(1.0, 10.0, 0.0)
    turtle.set_command(0.0, 0.0, 0.0, 0.0)
    turtle.queue_teleport(TeleportAbsolute(-0.5, 2.0, 0.0))
    result = turtle.update(DT, 0.0, canvas)
    assert result.wall_warning == (
        'Oh no! I hit the wall! (Clamping from [x=-0.500000, y=%f])' % (WORLD_SIZE - 2.0))
    assert result.wall_warning.endswith('y=9.088889])')
    assert (result.pose.x, result.pose.y) == pytest.approx((0.0, 2.0), abs=1e-6)


def test_wall_warning_repeats_and_velocity_is_kept(canvas):
    turtle = Turtle(WORLD_SIZE - 0.01, WORLD_CENTRE, 0.0)
    turtle.set_command(1.0, 0.0, 0.0, 0.0)
    results = run(turtle, canvas, 0.0, 5)
    assert all(result.wall_warning is not None for result in results)
    assert all(result.pose.x == pytest.approx(WORLD_SIZE) for result in results)
    assert results[-1].pose.linear_velocity == 1.0


def test_teleport_absolute_above_top_clamps_silently(canvas):
    turtle = Turtle(WORLD_CENTRE, WORLD_CENTRE, 0.0)
    turtle.queue_teleport(TeleportAbsolute(3.0, 50.0, 1.0))
    result = turtle.update(DT, 0.0, canvas)
    assert result.wall_warning is None
    assert (result.pose.x, result.pose.y, result.pose.theta) == pytest.approx(
        (3.0, WORLD_SIZE, 1.0), abs=1e-6)


def test_teleport_relative_rotates_first_then_moves(canvas):
    turtle = Turtle(WORLD_CENTRE, WORLD_CENTRE, 0.0)
    turtle.queue_teleport(TeleportRelative(2.0, math.pi / 2))
    pose = turtle.update(DT, 0.0, canvas).pose
    assert (pose.x, pose.y, pose.theta) == pytest.approx(
        (WORLD_CENTRE, WORLD_CENTRE + 2.0, math.pi / 2), abs=1e-6)


def test_teleports_apply_in_order_and_keep_velocity(canvas):
    turtle = Turtle(WORLD_CENTRE, WORLD_CENTRE, 0.0)
    turtle.set_command(1.0, 0.0, 0.0, 0.0)
    turtle.queue_teleport(TeleportAbsolute(1.0, 1.0, 0.0))
    turtle.queue_teleport(TeleportRelative(1.0, 0.0))
    pose = turtle.update(DT, 0.0, canvas).pose
    assert (pose.x, pose.y) == pytest.approx((2.0 + DT, 1.0), abs=1e-6)
    assert pose.linear_velocity == 1.0
    assert turtle.update(DT, 0.0, canvas).pose.x == pytest.approx(2.0 + 2 * DT, abs=1e-6)


def test_published_fields_are_float32(canvas):
    turtle = Turtle(WORLD_CENTRE, WORLD_CENTRE, 0.0)
    turtle.set_command(0.1, 0.0, 0.1, 0.0)
    pose = turtle.update(DT, 0.0, canvas).pose
    assert all(float(numpy.float32(value)) == value for value in pose)


@pytest.mark.parametrize('a, b', [
    (1.0, 1.0 + 1e-13), (1.0, 1.0 + 1e-11), (0.0, 1e-13), (0.0, 1e-11),
    (5.5, 5.5), (499.0, 499.0 + 1e-10), (-2.0, 2.0),
])
def test_position_change_uses_qt_fuzzy_point_compare(a, b):
    assert qt_fuzzy_equal(a, b) == (QPointF(a, 0.0) == QPointF(b, 0.0))
