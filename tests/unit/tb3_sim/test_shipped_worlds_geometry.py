"""The worlds converted from turtlebot3_gazebo (noetic-devel): turtlebot3_house and turtlebot3_stage_1..4 load,
span the area the original SDF walls span, carry the original model names, and their launch files spawn the robot
at the original's defaults, clear of every wall and piece of furniture."""

import math
import xml.etree.ElementTree as ElementTree
from pathlib import Path
from typing import NamedTuple

import pytest

from tb3_sim.core.geometry import Pose2D
from tb3_sim.core.shapes import Box, Circle, Polygon, Segment, visible_at
from tb3_sim.core.world import World
from tb3_sim.core.world_file import load_world, shipped_world_path

LAUNCH_DIR = Path(__file__).resolve().parents[3] / "catkin_ws" / "src" / "compat" / "turtlebot3_gazebo" / "launch"

WALL_THICKNESS_M = 0.15   # every wall box of the house, the square and the plaza
# The Waffle (turtlebot3_waffle.urdf.xacro) in base_footprint: its base box spans x -0.197..0.069, y +-0.133 (the
# wheels, to y +-0.153 within x +-0.033, stay inside the circle through its rear corners); LiDAR plane 0.132 m.
WAFFLE_REAR_X_M, WAFFLE_HALF_WIDTH_M = -0.197, 0.133
SCAN_PLANE_M = 0.132


class Original(NamedTuple):
    """What the original world and launch file say: the static model's name, the other models' names, the
    robot's spawn name and pose (launch defaults), and the walls' outer bounds (x_min, x_max, y_min, y_max)."""

    static_model: str
    models: tuple
    robot_name: str
    spawn: tuple
    bounds: tuple


# Bounds from the SDF: house walls Wall_85 (x = -7.5), Wall_81 (centre x 5.07752, 5 m long), Wall_83/_84
# (y = 5.275) and Wall_94 (y = -5.275); square walls at +-1.925, 4 m long; plaza walls at +-2.425, 5 m long.
HALF = WALL_THICKNESS_M / 2
ORIGINALS = {
    "turtlebot3_house": Original("turtlebot3_house", (), "turtlebot3", (-3.0, 1.0),
                                 (-7.5 - HALF, 5.07752 + 5 / 2, -5.275 - HALF, 5.275 + HALF)),
    "turtlebot3_stage_1": Original("turtlebot3_square", (), "turtlebot3_burger", (0.0, 0.0),
                                   (-1.925 - HALF, 1.925 + HALF, -4 / 2, 4 / 2)),
    "turtlebot3_stage_2": Original("turtlebot3_square", (), "turtlebot3_burger", (0.0, 0.0),
                                   (-1.925 - HALF, 1.925 + HALF, -4 / 2, 4 / 2)),
    "turtlebot3_stage_3": Original("turtlebot3_square", (), "turtlebot3_burger", (0.0, 0.0),
                                   (-1.925 - HALF, 1.925 + HALF, -4 / 2, 4 / 2)),
    "turtlebot3_stage_4": Original("turtlebot3_plaza", ("obstacle_1", "obstacle_2"), "turtlebot3_burger",
                                   (-0.7, 0.0), (-2.425 - HALF, 2.425 + HALF, -5 / 2, 5 / 2)),
}
WORLDS = sorted(ORIGINALS)

# The stage_2/_3 pillars (r 0.15 m, 0.5 m tall) and the stage_4 obstacles (r 0.12 m, 0.25 m once resting on the floor).
PILLARS = {(-0.6, -0.6), (-0.6, 0.6), (0.6, -0.6), (0.6, 0.6)}


def world(name):
    return load_world(shipped_world_path(name))


def shape_points(shape):
    """Corner points bounding a static shape (a circle by its bounding square)."""
    if isinstance(shape, Polygon):
        return list(shape.points)
    if isinstance(shape, Segment):
        return [shape.start, shape.end]
    (x, y), r = shape.center, shape.radius
    return [(x - r, y - r), (x + r, y + r)]


def model_points(spec):
    if isinstance(spec.shape, Box):
        return [spec.pose.compose(x, y) for x, y in spec.shape.corners()]
    r = spec.shape.radius
    return [(spec.pose.x - r, spec.pose.y - r), (spec.pose.x + r, spec.pose.y + r)]


def bounds(description):
    points = [p for s in description.static_shapes for p in shape_points(s)]
    points += [p for m in description.models for p in model_points(m)]
    xs, ys = [x for x, _ in points], [y for _, y in points]
    return min(xs), max(xs), min(ys), max(ys)


def distance_to_segment(point, a, b):
    (px, py), (ax, ay), (bx, by) = point, a, b
    ex, ey = bx - ax, by - ay
    along = max(0.0, min(1.0, ((px - ax) * ex + (py - ay) * ey) / (ex * ex + ey * ey)))
    return math.hypot(px - ax - along * ex, py - ay - along * ey)


def distance_to_shape(point, shape):
    """Distance from `point` to a static shape's outline, negative inside a polygon or circle."""
    if isinstance(shape, Circle):
        return math.hypot(point[0] - shape.center[0], point[1] - shape.center[1]) - shape.radius
    if isinstance(shape, Segment):
        return distance_to_segment(point, shape.start, shape.end)
    edges = list(zip(shape.points, shape.points[1:] + shape.points[:1]))
    outline = min(distance_to_segment(point, a, b) for a, b in edges)
    crossings = [(bx - ax) * (point[1] - ay) - (by - ay) * (point[0] - ax) for (ax, ay), (bx, by) in edges]
    inside = all(c > 0 for c in crossings) or all(c < 0 for c in crossings)
    return -outline if inside else outline


def turning_radius_m():
    """The farthest point of the Waffle's collision outline from base_footprint: what it needs to turn on the spot."""
    return math.hypot(WAFFLE_REAR_X_M, WAFFLE_HALF_WIDTH_M)


def launch_args(world_name):
    """(declared arg defaults, the include's arg values) of turtlebot3_gazebo/launch/<world_name>.launch."""
    root = ElementTree.parse(LAUNCH_DIR / f"{world_name}.launch").getroot()
    declared = {arg.get("name"): arg.get("default") for arg in root.findall("arg")}
    include = root.find("include")
    assert include.get("file") == "$(dirname)/includes/tb3_sim_world.launch.xml"
    assert include.get("pass_all_args") == "true"
    return declared, {arg.get("name"): arg.get("value") for arg in include.findall("arg")}


@pytest.mark.parametrize("name", WORLDS)
def test_world_loads_with_the_original_model_names(name):
    description, original = world(name), ORIGINALS[name]
    assert description.name == name
    assert description.static_model == original.static_model
    assert tuple(m.name for m in description.models) == original.models


@pytest.mark.parametrize("name", WORLDS)
def test_bounding_box_is_the_original_walls(name):
    assert bounds(world(name)) == pytest.approx(ORIGINALS[name].bounds, abs=1e-3)


def test_house_spans_about_15_2_by_10_7_m():
    x_min, x_max, y_min, y_max = bounds(world("turtlebot3_house"))
    assert (x_min, x_max, y_min, y_max) == pytest.approx((-7.58, 7.58, -5.35, 5.35), abs=0.005)


@pytest.mark.parametrize("name", WORLDS)
def test_launch_file_has_the_original_name_args_and_defaults(name):
    declared, passed = launch_args(name)
    original = ORIGINALS[name]
    assert declared == {"model": "$(optenv TURTLEBOT3_MODEL waffle)", "x_pos": str(original.spawn[0]),
                        "y_pos": str(original.spawn[1]), "z_pos": "0.0"}
    assert passed == {"world": name, "robot_name": original.robot_name}


@pytest.mark.parametrize("name", WORLDS)
def test_spawn_pose_leaves_room_to_turn_on_the_spot(name):
    description, spawn = world(name), ORIGINALS[name].spawn
    clearances = [distance_to_shape(spawn, s) for s in description.static_shapes]
    clearances += [math.hypot(spawn[0] - m.pose.x, spawn[1] - m.pose.y) - m.shape.radius for m in description.models]
    assert min(clearances) > turning_radius_m()


@pytest.mark.parametrize("name", WORLDS)
def test_robot_at_the_spawn_pose_is_not_pushed_and_turns_freely(name):
    spawn = Pose2D(*ORIGINALS[name].spawn, 0.0)
    sim = World(world(name), spawn)
    sim.run(0.5)
    assert sim.robot.pose == pytest.approx(spawn, abs=1e-6)
    sim.robot.set_command(0.0, 1.5)
    sim.run(2.0)
    assert (sim.robot.pose.x, sim.robot.pose.y) == pytest.approx(ORIGINALS[name].spawn, abs=1e-3)


def test_house_has_the_floor_boxes_of_21_wall_links_and_the_furniture():
    shapes = world("turtlebot3_house").static_shapes
    walls = [s for s in shapes if isinstance(s, Polygon) and s.height in (2.5, 1.0, 0.5)]
    assert len(walls) == 32, "21 links: 10 of one box, 11 of two (beside a doorway, or a wall end and a sill)"
    assert sorted({s.height for s in shapes}) == [0.02, 0.04, 0.06, 0.5, 0.7366, 0.74, 1.0, 1.02, 1.2, 2.5]
    legs = sorted(s.center for s in shapes if isinstance(s, Circle) and s.radius == 0.02)
    table_x, table_y = -2.65728, 2.42376
    corners = sorted((table_x + dx, table_y + dy) for dx in (-0.68, 0.68) for dy in (-0.38, 0.38))
    assert [c for leg in legs for c in leg] == pytest.approx([c for corner in corners for c in corner], abs=1e-4)
    cans = [(s.center, s.radius, s.height) for s in shapes if isinstance(s, Circle) and s.radius > 0.02]
    assert cans == [((1.88346, 1.91193), 0.2286, 0.7366), ((-4.69354, 4.89439), 0.2286, 0.7366)]


@pytest.mark.parametrize("name", ["turtlebot3_stage_2", "turtlebot3_stage_3"])
def test_stage_pillars_are_the_originals_and_seen_by_the_scan(name):
    pillars = [s for s in world(name).static_shapes if isinstance(s, Circle)]
    assert {s.center for s in pillars} == PILLARS
    assert {(s.radius, s.height) for s in pillars} == {(0.15, 0.5)}
    assert all(visible_at(s, SCAN_PLANE_M) for s in pillars)


def test_stage_4_obstacles_are_dynamic_cylinders_above_the_scan_plane():
    models = world("turtlebot3_stage_4").models
    assert [(m.name, m.pose.x, m.pose.y, m.static) for m in models] == [
        ("obstacle_1", 2.0, 2.0, False), ("obstacle_2", -2.0, -2.0, False)]
    assert {(m.shape.radius, m.shape.height, m.mass_kg) for m in models} == {(0.12, 0.25, 1.0)}
    assert all(visible_at(m.shape, SCAN_PLANE_M) for m in models)
