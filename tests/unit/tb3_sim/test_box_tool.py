"""The box tool's gestures on a real World (no Qt): place, pick, drag, delete; the robot is never picked."""
import pytest

from tb3_sim.core.geometry import Pose2D
from tb3_sim.core.shapes import Box, Cylinder
from tb3_sim.core.world import World
from tb3_sim.core.world_file import ModelSpec, load_world, shipped_world_path
from tb3_sim.view.box_tool import BoxTool, model_at, next_box_name


@pytest.fixture
def world():
    return World(load_world(shipped_world_path("empty")), Pose2D(0.0, 0.0, 0.0))


def test_model_at_hits_rotated_boxes_and_cylinders(world):
    world.spawn_model(ModelSpec("long", Box(1.0, 0.2, 0.3), Pose2D(2.0, 0.0, 1.5707963)))
    world.spawn_model(ModelSpec("can", Cylinder(0.1, 0.3), Pose2D(-2.0, 0.0, 0.0)))
    assert model_at(world, 2.0, 0.45) == "long"
    assert model_at(world, 2.45, 0.0) is None
    assert model_at(world, -2.05, 0.05) == "can"
    assert model_at(world, 0.0, 0.0) is None


def test_click_on_the_floor_places_numbered_boxes(world, fake_sim):
    tool = BoxTool(fake_sim(world))
    assert tool.left_press(1.0, 0.0) == "placed 'box_1' at (1.00, 0.00)"
    tool.release()
    assert tool.left_press(1.0, 1.0) == "placed 'box_2' at (1.00, 1.00)"
    assert world.get_model_state("box_2").pose.x == pytest.approx(1.0)
    assert next_box_name(world) == "box_3"


def test_no_box_on_the_robot(world, fake_sim):
    assert BoxTool(fake_sim(world)).left_press(0.0, 0.0).startswith("no box placed: model 'box_1' would overlap")


def test_drag_moves_the_picked_model_and_release_stops(world, fake_sim):
    sim = fake_sim(world)
    tool = BoxTool(sim)
    tool.left_press(1.0, 0.0)
    tool.release()
    assert tool.left_press(1.05, 0.05) == "dragging 'box_1'"
    tool.drag(1.5, -1.0)
    tool.release()
    tool.drag(3.0, 3.0)
    assert world.get_model_state("box_1").pose[:2] == pytest.approx((1.5, -1.0))
    assert sim.teleports == 1


def test_right_click_deletes_a_model_but_not_the_robot(world, fake_sim):
    tool = BoxTool(fake_sim(world))
    tool.left_press(1.0, 0.0)
    assert tool.right_click(1.0, 0.0) == "deleted 'box_1'"
    assert not world.has_model("box_1")
    assert tool.right_click(0.0, 0.0) is None
