"""shape_server's polygon controller: the result's geometry and a closed-loop pentagon on a core Turtle."""
import math

import numpy
import pytest

from roslab.turtle_driver import drive
from turtle_actionlib.shape_controller import ShapeController, ShapeResult, normalize_angle_positive
from turtlesim.core.canvas import Canvas
from turtlesim.core.constants import DT, WORLD_CENTRE
from turtlesim.core.turtle import Turtle


def test_shape_result_for_five_edges_radius_1_3():
    controller = ShapeController(5, 1.3)
    assert controller.result == ShapeResult(1.884955644607544, 1.0517220497131348)
    assert all(float(numpy.float32(value)) == value for value in controller.result)
    assert controller.side_length == pytest.approx(2 * 1.3 * math.sin(math.pi / 5), rel=1e-6)


def test_normalize_angle_positive_range():
    assert normalize_angle_positive(-0.5) == pytest.approx(2 * math.pi - 0.5)
    assert normalize_angle_positive(7.0) == pytest.approx(7.0 - 2 * math.pi)
    assert normalize_angle_positive(0.0) == 0.0


def test_shape_controller_drives_a_pentagon_through_five_corners():
    controller = ShapeController(5, 1.3)
    side = controller.side_length
    steps = []

    def step(pose):
        result = controller.on_pose(pose)
        steps.append(result)
        return 'done' if result.succeeded else result.command

    poses = drive(Turtle(WORLD_CENTRE, WORLD_CENTRE, 0.0), step, 4000)
    assert steps[-1].succeeded and not any(s.succeeded for s in steps[:-1])
    assert 900 < len(poses) < 1600
    corner = (WORLD_CENTRE, WORLD_CENTRE)
    for edge in range(5):
        heading = edge * 2 * math.pi / 5
        corner = (corner[0] + side * math.cos(heading), corner[1] + side * math.sin(heading))
        nearest = min(math.hypot(p.x - corner[0], p.y - corner[1]) for p in poses)
        assert nearest < 1e-3, 'corner %d missed by %f m' % (edge + 1, nearest)
    assert (poses[-1].x, poses[-1].y) == pytest.approx((WORLD_CENTRE, WORLD_CENTRE), abs=1e-3)
    assert all(p.angular_velocity >= 0.0 for p in poses)


def test_shape_controller_succeeds_at_once_for_no_edges():
    step = ShapeController(0, 1.0).on_pose(Turtle(1.0, 1.0, 0.0).update(DT, 0.0, Canvas()).pose)
    assert step.succeeded and step.command is None
