"""World files: the shipped worlds load, and every kind of mistake names the file and the key."""

from pathlib import Path

import pytest

from tb3_sim.core.errors import SimError, WorldFileError
from tb3_sim.core.geometry import Pose2D
from tb3_sim.core.shapes import Box, Circle, Cylinder, Polygon
from tb3_sim.core.world_file import load_world, parse_world, shipped_world_path

INVALID = Path(__file__).parent / "fixtures" / "invalid_worlds"


@pytest.mark.parametrize("file_name, key", [
    ("unknown_top_key.yaml", "colour"),
    ("missing_name.yaml", "name"),
    ("box_size_two_numbers.yaml", "models[0].size"),
    ("negative_radius.yaml", "static[0].radius"),
    ("unknown_model_key.yaml", "models[0].colour"),
    ("unknown_model_type.yaml", "models[0].type"),
    ("unknown_color_name.yaml", "models[0].color"),
    ("color_out_of_range.yaml", "static[0].color"),
    ("concave_polygon.yaml", "static[0].points"),
    ("duplicate_model_name.yaml", "models[1].name"),
    ("static_not_bool.yaml", "models[0].static"),
    ("pose_not_number.yaml", "models[0].pose[2]"),
    ("segment_nan.yaml", "static[0].end[0]"),
    ("not_yaml.yaml", "<file>"),
    ("static_model_reserved.yaml", "static_model"),
    ("model_named_ground_plane.yaml", "models[0].name"),
    ("top_is_list.yaml", "<top>"),
])
def test_invalid_world_names_file_and_key(file_name, key):
    path = INVALID / file_name
    with pytest.raises(WorldFileError) as caught:
        load_world(path)
    assert caught.value.key == key
    assert caught.value.path == str(path)
    assert str(path) in str(caught.value) and key in str(caught.value)


def test_missing_file_is_a_world_file_error():
    with pytest.raises(WorldFileError, match="cannot read") as caught:
        load_world(INVALID / "no_such_world.yaml")
    assert isinstance(caught.value, SimError)


def test_unknown_key_message_lists_the_allowed_keys():
    with pytest.raises(WorldFileError, match="allowed: floor, models, name, static, static_model, static_models"):
        parse_world({"name": "w", "colour": "red"})


def test_star_polygon_is_rejected_as_not_convex():
    star = [[1, 0], [-0.81, 0.59], [0.31, -0.95], [0.31, 0.95], [-0.81, -0.59]]
    with pytest.raises(WorldFileError, match="convex"):
        parse_world({"name": "w", "static": [{"type": "polygon", "points": star}]})


def test_defaults_of_a_model():
    world = parse_world({"name": "w", "models": [{"name": "b", "type": "box", "size": [1, 2, 3]}]})
    (model,) = world.models
    assert model.shape == Box(1.0, 2.0, 3.0)
    assert model.pose == Pose2D(0.0, 0.0, 0.0)
    assert model.static is False and model.mass_kg == 1.0


def test_empty_world_has_nothing():
    world = load_world(shipped_world_path("empty"))
    assert world.name == "empty" and world.static_model is None
    assert world.static_shapes == () and world.models == ()


def test_turtlebot3_world_layout():
    world = load_world(shipped_world_path("turtlebot3_world"))
    assert world.static_model == "ros_symbol"
    pillars = [s for s in world.static_shapes if isinstance(s, Circle)]
    assert sorted(p.center for p in pillars) == sorted(
        (x, y) for x in (-1.1, 0.0, 1.1) for y in (-1.1, 0.0, 1.1))
    assert all(p.radius == 0.15 and p.height == 0.5 for p in pillars)
    polygons = [s for s in world.static_shapes if isinstance(s, Polygon)]
    assert len(polygons) == 6 + 4 + 1
    assert min(x for p in polygons for x, _ in p.points) == -3.3
    assert max(y for p in polygons for _, y in p.points) == pytest.approx(3.401)


def test_approach_arena_has_a_box_ahead_of_the_origin():
    world = load_world(shipped_world_path("approach_arena"))
    target = next(m for m in world.models if m.name == "target_box")
    assert target.pose.x == pytest.approx(1.5) and target.pose.y == 0.0
    assert any(isinstance(m.shape, Cylinder) and m.static for m in world.models)


def test_colors_by_name_hex_gazebo_material_and_channels():
    world = parse_world({"name": "w", "static": [
        {"type": "circle", "center": [0, 0], "radius": 0.1, "color": "#ff8000"},
        {"type": "circle", "center": [1, 0], "radius": 0.1, "color": [0.0, 0.5, 1.0]},
        {"type": "circle", "center": [2, 0], "radius": 0.1}],
        "models": [{"name": "b", "type": "box", "size": [0.3, 0.3, 0.3], "color": "Gazebo/Red"},
                   {"name": "c", "type": "cylinder", "radius": 0.1, "height": 0.2, "color": "yellow"}]})
    assert [s.rgb for s in world.static_shapes] == [(255, 128, 0), (0, 128, 255), None]
    assert [m.rgb for m in world.models] == [(255, 0, 0), (255, 255, 0)]


def test_the_shipped_camera_worlds_load():
    fruit = load_world(shipped_world_path("fruit_world"))
    assert {m.name: m.rgb for m in fruit.models} == {"apple": (255, 0, 0), "banana": (255, 255, 0)}
    pillars = load_world(shipped_world_path("colour_search")).models
    assert len({m.rgb for m in pillars}) == 6
