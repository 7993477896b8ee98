"""Tutorial helpers: shape_server controller, draw_square state machine, teleop key table."""
import math

import numpy
import pytest

from turtlesim.canvas import Canvas
from turtlesim.constants import DT, WORLD_CENTRE
from turtlesim.draw_square import SquareDriver, SquareState
from turtlesim.log import LogLevel
from turtlesim.shape_controller import ShapeController, ShapeResult, normalize_angle_positive
from turtlesim.teleop_keys import BANNER, KEY_QUIT, command_for_key
from turtlesim.turtle import Turtle


def drive(turtle, controller_step, ticks):
    """Run turtle ticks at 62.5 Hz; each pose goes to `controller_step`, whose command takes
    effect from the next tick (as a published Twist reaches the next spinOnce). Returns the
    poses; stops early when `controller_step` returns the string 'done'."""
    canvas = Canvas()
    poses = []
    for k in range(1, ticks + 1):
        now = k * DT
        pose = turtle.update(DT, now, canvas).pose
        poses.append(pose)
        command = controller_step(pose)
        if command == 'done':
            break
        if command is not None:
            turtle.set_command(command[0], 0.0, command[1], now)
    return poses


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


def test_draw_square_corners_and_logs(log):
    driver = SquareDriver(log)
    corners = []

    def step(pose):
        state = driver.state
        command = driver.on_timer(pose)
        if state is SquareState.STOP_FORWARD and driver.state is SquareState.TURN:
            corners.append((pose.x, pose.y))
        return command

    drive(Turtle(WORLD_CENTRE, WORLD_CENTRE, 0.0), step, 2500)
    assert driver.on_timer(None) is None
    expected = [(7.544, 5.544), (7.544, 7.544), (5.544, 7.544), (5.544, 5.544)]
    assert len(corners) >= 4
    for (x, y), (expected_x, expected_y) in zip(corners, expected):
        assert abs(x - expected_x) < 0.1 and abs(y - expected_y) < 0.1
    texts = log.texts(LogLevel.INFO)
    assert texts[0] == 'New goal [7.544445 5.544445, 0.000000]'
    assert texts[1] == 'Reached goal'
    assert texts[2].startswith('New goal [7.4')


def test_draw_square_waits_for_a_pose(log):
    assert SquareDriver(log).on_timer(None) is None
    assert log.events == []


@pytest.mark.parametrize('key, command', [
    (0x41, (2.0, 0.0)), (0x42, (-2.0, 0.0)), (0x44, (0.0, 2.0)), (0x43, (0.0, -2.0)),
    (ord('A'), (2.0, 0.0)), (0x1B, None), (ord('['), None), (ord('x'), None), (KEY_QUIT, None),
])
def test_teleop_key_table(key, command):
    assert command_for_key(key) == command


def test_teleop_scales_and_banner():
    assert command_for_key(0x41, 0.5, 3.0) == (0.5, 0.0)
    assert command_for_key(0x44, 0.5, 3.0) == (0.0, 3.0)
    assert BANNER[2] == "Use arrow keys to move the turtle. 'q' to quit."
