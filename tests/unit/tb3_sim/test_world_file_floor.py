"""World files' floor layer and several static models: what they load into, and every mistake named by file and
key."""

import math
from pathlib import Path

import cv2
import numpy as np
import pytest
import yaml

from tb3_sim.core.errors import WorldFileError
from tb3_sim.core.floor import (
    ArcMarking,
    CircleMarking,
    CurveMarking,
    PolygonMarking,
    PolylineMarking,
    RectangleMarking,
    Stroke,
    TextMarking,
)
from tb3_sim.core.floor_file import MAX_IMAGE_SIDE_PX
from tb3_sim.core.shapes import Polygon
from tb3_sim.core.world import World
from tb3_sim.core.world_file import load_world, parse_world

EVERY_MARKING = Path(__file__).parent / "fixtures" / "floor_worlds" / "every_marking.yaml"


def test_every_marking_kind_loads_into_its_typed_object():
    world = load_world(EVERY_MARKING)
    floor = world.floor
    assert floor.size == (6.0, 4.0) and floor.center == (0.5, 0.0) and floor.rgb == (255, 255, 255)
    assert floor.bounds() == (-2.5, -2.0, 3.5, 2.0)
    kinds = [type(m) for m in floor.markings]
    assert kinds == [RectangleMarking, RectangleMarking, PolygonMarking, CircleMarking, CircleMarking, ArcMarking,
                     PolylineMarking, PolylineMarking, CurveMarking, TextMarking]
    filled, outline = floor.markings[:2]
    assert filled.stroke is None and filled.yaw_deg == 30.0 and filled.rgb == (0, 255, 0)
    assert outline.stroke == Stroke(0.02, (0.05, 0.03)) and outline.yaw_deg == 0.0
    arc = floor.markings[5]
    assert arc.stroke == Stroke(0.03, None, "end", pytest.approx(0.09)) and arc.rgb == (255, 0, 255)
    assert floor.markings[6].stroke == Stroke(0.05, None, "start", 0.2) and not floor.markings[6].closed
    assert floor.markings[7].closed and floor.markings[7].stroke.dash == (0.046, 0.023)
    text = floor.markings[9]
    assert (text.text, text.position, text.height, text.angle_deg, text.bold) == ("A", (2.5, 1.5), 0.3, 90.0, True)


def test_static_models_are_listed_by_name_and_their_shapes_are_the_worlds():
    world = load_world(EVERY_MARKING)
    assert world.static_model_names == ("navigation", "arena_walls")
    assert [len(m.shapes) for m in world.static_models] == [1, 2]
    assert len(world.static_shapes) == 3
    names = World(world, robot_name="turtlebot3_waffle").model_names()
    assert names == ["navigation", "arena_walls", "turtlebot3_waffle"]   # the floor model is the ground


def test_box_static_shape_is_the_rectangle_gazebo_gives():
    world = parse_world({"name": "w", "static": [
        {"type": "box", "center": [0.05, 2.45], "size": [4.9, 0.1], "yaw": math.pi / 2, "height": 0.3}]})
    (box,) = world.static_shapes
    assert isinstance(box, Polygon) and box.height == 0.3
    xs, ys = zip(*box.points)
    assert min(xs) == pytest.approx(0.0) and max(xs) == pytest.approx(0.1)
    assert min(ys) == pytest.approx(0.0) and max(ys) == pytest.approx(4.9)


def test_the_single_static_model_form_still_names_one_model():
    world = parse_world({"name": "w", "static_model": "walls", "static": [
        {"type": "circle", "center": [1, 1], "radius": 0.1}]})
    assert world.static_model_names == ("walls",) and world.floor is None


def test_floor_defaults():
    floor = parse_world({"name": "w", "floor": {"size": [2, 3]}}).floor
    assert floor.center == (0.0, 0.0) and floor.rgb == (255, 255, 255)
    assert floor.image is None and floor.markings == ()


def _png(path, width, height):
    pixels = np.zeros((height, width, 3), dtype=np.uint8)
    pixels[0, :] = (0, 0, 255)   # BGR red top row
    assert cv2.imwrite(str(path), pixels)


def test_floor_image_loads_relative_to_the_world_file(tmp_path):
    _png(tmp_path / "floor.png", 20, 10)
    path = tmp_path / "w.yaml"
    path.write_text(yaml.safe_dump({"name": "w", "floor": {"size": [4, 4], "image": {
        "file": "floor.png", "size": [2, 1], "center": [0.5, 0.5], "yaw_deg": 90}}}))
    image = load_world(path).floor.image
    assert image.pixels.shape == (10, 20, 3) and tuple(image.pixels[0, 0]) == (255, 0, 0)
    assert image.size == (2.0, 1.0) and image.center == (0.5, 0.5) and image.yaw_deg == 90.0


def test_jpeg_floor_image_loads(tmp_path):
    assert cv2.imwrite(str(tmp_path / "floor.jpg"), np.full((8, 16, 3), 200, dtype=np.uint8))
    path = tmp_path / "w.yaml"
    path.write_text(yaml.safe_dump({"name": "w", "floor": {"size": [4, 4], "image": {
        "file": "floor.jpg", "size": [2, 1]}}}))
    assert load_world(path).floor.image.pixels.shape == (8, 16, 3)


@pytest.mark.parametrize("content, problem", [
    (None, "cannot read"),
    (b"GIF89a not an image", "not a PNG or JPEG"),
    (b"\x89PNG\r\n\x1a\n\x00\x00\x00\rIHDR" + (5000).to_bytes(4, "big") + (10).to_bytes(4, "big") + b"\x08\x02",
     f"at most {MAX_IMAGE_SIDE_PX} px"),
    (b"\x89PNG\r\n\x1a\n\x00\x00\x00\rIHDR" + (10).to_bytes(4, "big") + (10).to_bytes(4, "big") + b"broken",
     "cannot be decoded"),
])
def test_bad_floor_images_are_refused_naming_the_file_and_key(tmp_path, content, problem):
    if content is not None:
        (tmp_path / "floor.png").write_bytes(content)
    path = tmp_path / "w.yaml"
    path.write_text(yaml.safe_dump({"name": "w", "floor": {"size": [4, 4], "image": {
        "file": "floor.png", "size": [2, 1]}}}))
    with pytest.raises(WorldFileError, match=problem) as caught:
        load_world(path)
    assert caught.value.key == "floor.image.file" and caught.value.path == str(path)


def _marking(**fields):
    return {"name": "w", "floor": {"size": [4, 4], "markings": [{"color": "red", **fields}]}}


M = "floor.markings[0]"


@pytest.mark.parametrize("data, key, problem", [
    ({"name": "w", "floor": {"center": [0, 0]}}, "floor.size", "missing"),
    ({"name": "w", "floor": {"size": [4, -1]}}, "floor.size[1]", "> 0"),
    ({"name": "w", "floor": {"size": [4, 4], "color": "mauve-ish"}}, "floor.color", "unknown colour"),
    ({"name": "w", "floor": {"size": [4, 4], "texture": "x"}}, "floor.texture", "unknown key"),
    ({"name": "w", "floor": {"size": [4, 4], "markings": {}}}, "floor.markings", "expected a list"),
    ({"name": "w", "floor": {"size": [4, 4], "image": {"file": "f.png"}}}, "floor.image.size", "missing"),
    ({"name": "w", "floor": {"size": [4, 4], "markings": [{"type": "star", "color": "red"}]}}, f"{M}.type",
     "expected one of"),
    ({"name": "w", "floor": {"size": [4, 4], "markings": [{"type": "circle", "center": [0, 0], "radius": 1}]}},
     f"{M}.color", "missing"),
    (_marking(type="rectangle", center=[0, 0], size=[1, 0]), f"{M}.size[1]", "> 0"),
    (_marking(type="rectangle", center=[0, 0], size=[1, 1], arrow="end", width=0.1), f"{M}.arrow", "unknown key"),
    (_marking(type="rectangle", center=[0, 0], size=[1, 1], dash=[0.1, 0.1]), f"{M}.dash", "only with `width`"),
    (_marking(type="polygon", points=[[0, 0], [1, 1], [1, 0], [0, 1]]), f"{M}.points", "simple"),
    (_marking(type="polygon", points=[[0, 0], [1, 1]]), f"{M}.points", "3 to"),
    (_marking(type="polygon", points=[[i, i % 2] for i in range(501)]), f"{M}.points", "3 to 500"),
    (_marking(type="circle", center=[0, "a"], radius=1), f"{M}.center[1]", "finite number"),
    (_marking(type="circle", center=[0, 0], radius=1, width=-0.1), f"{M}.width", "> 0"),
    (_marking(type="arc", center=[0, 0], radius=1, start_deg=0, end_deg=90), f"{M}.width", "missing"),
    (_marking(type="arc", center=[0, 0], radius=1, start_deg=10, end_deg=370, width=0.1), f"{M}.end_deg",
     "no length"),
    (_marking(type="arc", center=[0, 0], radius=1, start_deg=0, end_deg=90, width=0.1, arrow="middle"),
     f"{M}.arrow", "start, end"),
    (_marking(type="polyline", points=[[0, 0], [1, 0]], width=0.1, arrow_length=0.3), f"{M}.arrow_length",
     "only with `arrow`"),
    (_marking(type="polyline", points=[[0, 0], [1, 0], [1, 1]], width=0.1, closed=True, arrow="end"),
     f"{M}.arrow", "no ends"),
    (_marking(type="polyline", points=[[0, 0], [1, 0]], width=0.1, closed="yes"), f"{M}.closed", "true or false"),
    (_marking(type="polyline", points=[[0, 0], [1, 0]], width=0.1, dash=[0.1]), f"{M}.dash", "2 numbers"),
    (_marking(type="circle", center=[0, 0], radius=100, width=0.1, dash=[0.01, 0.01]), f"{M}.dash",
     "at most 20000"),
    (_marking(type="curve", points=[[0, 0], [1, 0], [1, 1], [2, 2], [3, 3]], width=0.1), f"{M}.points",
     r"3n \+ 1"),
    (_marking(type="text", text="", position=[0, 0], height=0.1), f"{M}.text", "printable text"),
    (_marking(type="text", text="A", position=[0, 0], height=0.1, bold=1), f"{M}.bold", "true or false"),
    (_marking(type="text", text="A", position=[0, 0]), f"{M}.height", "missing"),
    ({"name": "w", "static_model": "a", "static_models": []}, "static_model", "not both"),
    ({"name": "w", "static_models": [{"name": "a", "static": []}, {"name": "a", "static": []}]},
     "static_models[1].name", "already used"),
    ({"name": "w", "static_models": [{"name": "a", "static": []}], "models": [
        {"name": "a", "type": "box", "size": [1, 1, 1]}]}, "models[0].name", "already used"),
    ({"name": "w", "static_models": [{"name": "ground_plane", "static": []}]}, "static_models[0].name", "reserved"),
    ({"name": "w", "static_models": [{"name": "a", "static": [{"type": "box", "center": [0, 0]}]}]},
     "static_models[0].static[0].size", "missing"),
    ({"name": "w", "static_models": [{"name": "a"}]}, "static_models[0].static", "missing"),
])
def test_bad_floor_and_static_model_data_names_the_file_and_key(tmp_path, data, key, problem):
    path = tmp_path / "bad.yaml"
    path.write_text(yaml.safe_dump(data))
    with pytest.raises(WorldFileError, match=problem) as caught:
        load_world(path)
    assert caught.value.key == key
    assert str(path) in str(caught.value) and key in str(caught.value)


def test_a_world_without_a_floor_layer_keeps_gazebos_ground_plane():
    world = World(parse_world({"name": "w", "static_models": [{"name": "walls", "static": []}]}), robot_name=None)
    assert world.model_names() == ["ground_plane", "walls"]
