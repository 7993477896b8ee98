"""One description of the scene: every kind of floor marking becomes primitives that the top-down view draws where
the marking is, in its colour; dashes, arrowheads and outlines too."""

import json
import math

import cv2
import numpy as np
import pytest
from PyQt5.QtGui import QColor

from tb3_sim.core import primitives as primitive_kinds
from tb3_sim.core.floor_file import MARKING_KINDS
from tb3_sim.core.primitives import FilledPolygon, Polyline, to_data
from tb3_sim.core.scene_primitives import CONVERTERS, bezier_points, dashes, primitives_of
from tb3_sim.core.world_file import load_world, parse_world
from tb3_sim.view.primitive_painter import PAINTERS
from tb3_sim.view.renderer import render_image
from tb3_sim.view.scene import Scene

MAGENTA = (255, 0, 255)
WHITE = (255, 255, 255)


def floor_with(*markings):
    return parse_world({"name": "w", "floor": {"size": [4, 4], "color": "white", "markings": [
        {"color": "#ff00ff", **marking} for marking in markings]}}).floor


def top_down(floor):
    image, view = render_image(Scene(static_shapes=(), models=(), robots=(), floor=floor))

    def colour_at(x, y):
        column, row = view.to_pixel(x, y)
        return QColor(image.pixel(int(column), int(row))).getRgb()[:3]

    return colour_at


CURVE = [[-1.5, -1.0], [-1.0, 0.0], [0.0, -2.0], [0.5, -1.0]]


@pytest.mark.parametrize("marking, inside, outside", [
    ({"type": "rectangle", "center": [0.5, 0.5], "size": [0.6, 0.2], "yaw_deg": 90}, (0.5, 0.75), (0.75, 0.5)),
    ({"type": "rectangle", "center": [0.5, 0.5], "size": [0.6, 0.4], "width": 0.04}, (0.8, 0.5), (0.5, 0.5)),
    ({"type": "polygon", "points": [[0, 0], [1, 0], [1, 1], [0.5, 0.2], [0, 1]]}, (0.9, 0.5), (0.5, 0.6)),
    ({"type": "circle", "center": [-1, 1], "radius": 0.3}, (-1.0, 1.25), (-1.0, 1.35)),
    ({"type": "circle", "center": [-1, 1], "radius": 0.3, "width": 0.04}, (-1.0, 1.3), (-1.0, 1.0)),
    ({"type": "arc", "center": [0, 0], "radius": 1.0, "start_deg": 0, "end_deg": 90, "width": 0.05},
     (math.cos(math.pi / 4), math.sin(math.pi / 4)), (-1.0, 0.0)),
    ({"type": "polyline", "points": [[-1.5, 1.5], [1.5, 1.5], [1.5, -1.5]], "width": 0.05}, (1.5, 0.0), (0.0, 0.0)),
    ({"type": "polyline", "points": [[-1, -1], [1, -1], [1, 0]], "width": 0.05, "closed": True}, (0.0, -0.5),
     (0.5, -0.2)),
    ({"type": "curve", "points": CURVE, "width": 0.05}, tuple(bezier_points(CURVE)[len(bezier_points(CURVE)) // 2]),
     (-1.0, 0.0)),
    ({"type": "text", "text": "I", "position": [1.0, -1.5], "height": 0.4}, (1.0, -1.5), (1.0, -1.0)),
])
def test_every_kind_of_marking_draws_in_the_top_down_scene(marking, inside, outside):
    colour_at = top_down(floor_with(marking))
    assert colour_at(*inside) == MAGENTA
    assert colour_at(*outside) == WHITE


def test_a_dashed_stroke_draws_its_dashes_and_leaves_its_gaps():
    colour_at = top_down(floor_with({"type": "polyline", "points": [[-1.5, 0], [1.5, 0]], "width": 0.05,
                                     "dash": [0.2, 0.1]}))
    assert colour_at(-1.4, 0.0) == MAGENTA and colour_at(-1.25, 0.0) == WHITE and colour_at(-1.1, 0.0) == MAGENTA


def test_an_arrowhead_is_wider_than_its_stroke_at_the_end_it_names():
    colour_at = top_down(floor_with({"type": "polyline", "points": [[-1, 0], [1, 0]], "width": 0.04,
                                     "arrow": "end", "arrow_length": 0.4}))
    assert colour_at(0.85, 0.06) == MAGENTA        # the head, beside the stroke
    assert colour_at(-0.85, 0.06) == WHITE         # no head at the start
    assert colour_at(1.02, 0.0) == WHITE           # the tip is the end point


def test_a_floor_image_draws_with_its_top_row_at_plus_y(tmp_path):
    pixels = np.zeros((2, 1, 3), dtype=np.uint8)
    pixels[0] = (0, 0, 255)   # BGR: red on top
    cv2.imwrite(str(tmp_path / "f.png"), pixels)
    (tmp_path / "w.yaml").write_text(json.dumps({"name": "w", "floor": {"size": [4, 4], "image": {
        "file": "f.png", "size": [2, 2]}}}))
    colour_at = top_down(load_world(tmp_path / "w.yaml").floor)
    assert colour_at(0.0, 0.6)[0] > 200 and colour_at(0.0, -0.6)[0] < 50


def test_dashes_follow_the_path_length():
    pieces = dashes(np.array([[0.0, 0.0], [1.0, 0.0], [1.0, 1.0]]), 0.3, 0.2)
    starts = [tuple(piece[0]) for piece in pieces]
    assert starts == [(0.0, 0.0), (0.5, 0.0), pytest.approx((1.0, 0.0)), (1.0, 0.5)]
    assert tuple(pieces[2][-1]) == pytest.approx((1.0, 0.3))


def test_every_marking_kind_and_primitive_has_its_converter_painter_and_data():
    marking_classes = {type(m) for m in parse_world({"name": "w", "floor": {"size": [4, 4], "markings": [
        {"type": "rectangle", "center": [0, 0], "size": [1, 1], "color": "red"},
        {"type": "polygon", "points": [[0, 0], [1, 0], [1, 1]], "color": "red"},
        {"type": "circle", "center": [0, 0], "radius": 1, "color": "red"},
        {"type": "arc", "center": [0, 0], "radius": 1, "start_deg": 0, "end_deg": 30, "width": 0.1, "color": "red"},
        {"type": "polyline", "points": [[0, 0], [1, 0]], "width": 0.1, "color": "red"},
        {"type": "curve", "points": CURVE, "width": 0.1, "color": "red"},
        {"type": "text", "text": "A", "position": [0, 0], "height": 0.2, "color": "red"}]}}).floor.markings}
    assert len(marking_classes) == len(MARKING_KINDS)
    assert marking_classes <= set(CONVERTERS)
    kinds = {primitive_kinds.FilledPolygon, primitive_kinds.Polyline, primitive_kinds.Disc, primitive_kinds.Text,
             primitive_kinds.Image}
    assert set(PAINTERS) == kinds


def test_primitives_travel_as_json_data():
    floor = floor_with({"type": "polyline", "points": [[0, 0], [1, 0]], "width": 0.05},
                       {"type": "text", "text": "A", "position": [0, 0], "height": 0.2})
    data = json.loads(json.dumps([to_data(p) for p in primitives_of(floor)]))
    assert [d["kind"] for d in data] == ["FilledPolygon", "Polyline", "Text"]
    assert data[1] == {"kind": "Polyline", "points": [[0, 0], [1, 0]], "width": 0.05, "rgb": [255, 0, 255],
                       "closed": False}
    assert isinstance(primitives_of(floor)[0], FilledPolygon) and isinstance(primitives_of(floor)[1], Polyline)
