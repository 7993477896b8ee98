"""The page's picture of tb3_sim's world: walls and models from the world markers, LiDAR hits in the world
frame, and the trail sent to pages a few points at a time."""
import json
import math

import pytest

from lab_web.scene import (
    ADD,
    CUBE,
    CYLINDER,
    LINE_LIST,
    TRAIL_JUMP_M,
    TRAIL_MAX_POINTS,
    TRIANGLE_LIST,
    MarkerData,
    Pose2D,
    Trail,
    compose,
    scan_points,
    scene_primitives,
    sensor_offset,
    with_scene_bounds,
    world_content,
)

DELETE_ALL = 3
ORIGIN = Pose2D(0.0, 0.0, 0.0)


def marker(ns, kind, pose=ORIGIN, scale=(1.0, 1.0), points=(), text="", action=ADD):
    return MarkerData(ns, kind, action, pose, scale[0], scale[1], tuple(points), text)


def test_world_markers_become_shapes_models_and_robots():
    world = world_content([
        marker("", 0, action=DELETE_ALL),
        marker("static", TRIANGLE_LIST, points=[(0, 0), (4, 0), (4, 1), (0, 0), (4, 1), (0, 1)]),
        marker("static", LINE_LIST, points=[(-1, -1), (-1, 2)]),
        marker("static", CYLINDER, Pose2D(2, 2, 0), scale=(0.3, 0.3)),
        marker("models", CUBE, Pose2D(1.5, 0.5, math.pi / 2), scale=(0.4, 0.2), text="box_1"),
        marker("models", CYLINDER, Pose2D(3, 0, 0), scale=(0.2, 0.2), text="can"),
        marker("robots", CUBE, Pose2D(0, 0, 0), scale=(0.27, 0.3), text="turtlebot3_waffle"),
    ])
    assert [shape["kind"] for shape in world["static"]] == ["polygon", "segment", "circle"]
    assert world["static"][0]["points"] == [[0, 0], [4, 0], [4, 1], [0, 1]]   # the fan of two triangles, whole
    assert world["static"][2] == {"kind": "circle", "x": 2, "y": 2, "r": 0.15}
    assert world["models"] == [
        {"name": "box_1", "x": 1.5, "y": 0.5, "yaw": 1.5708, "kind": "box", "sx": 0.4, "sy": 0.2},
        {"name": "can", "x": 3, "y": 0, "yaw": 0.0, "kind": "circle", "r": 0.1}]
    assert world["robots"][0]["name"] == "turtlebot3_waffle"
    # the view fits the walls (plus a margin), not the models, so dragging a box does not move it
    assert world["bounds"] == [-1.5, -1.5, 4.5, 2.65]


def test_triangles_that_do_not_fan_out_stay_triangles():
    world = world_content([marker("static", TRIANGLE_LIST, points=[(0, 0), (1, 0), (0, 1), (5, 5), (6, 5), (5, 6)])])
    assert [shape["points"] for shape in world["static"]] == [[[0, 0], [1, 0], [0, 1]], [[5, 5], [6, 5], [5, 6]]]


def test_an_empty_world_is_shown_around_the_origin():
    assert world_content([marker("robots", CUBE, text="tb3")])["bounds"] == [-3.0, -3.0, 3.0, 3.0]


def test_scan_hits_are_placed_in_the_world_frame_and_misses_dropped():
    sensor = compose(Pose2D(1.0, 2.0, math.pi / 2), Pose2D(-0.064, 0.0, 0.0))   # the Waffle's LiDAR offset
    assert sensor.x == pytest.approx(1.0) and sensor.y == pytest.approx(2.0 - 0.064)
    points = scan_points([1.0, math.inf, 0.05, math.nan, 2.0], 0.0, math.pi / 2, 0.12, 3.5, sensor)
    # beam 0 looks along the robot's heading (+y), beam 4 (2 pi) too; inf, too-near and nan are no hits
    assert points == [[1.0, pytest.approx(2.936)], [1.0, pytest.approx(3.936)]]


def test_the_trail_goes_to_pages_incrementally():
    trail = Trail()
    for i in range(10):
        trail.add(i * 0.015, 0.0)      # 1.5 cm steps: every other one makes a point (2 cm apart at least)
    reset, points, cursor = trail.since(None)
    assert reset and points == [[0.0, 0.0], [0.03, 0.0], [0.06, 0.0], [0.09, 0.0], [0.12, 0.0]]
    assert trail.since(cursor)[:2] == (False, [])
    trail.add(0.15, 0.0)
    reset, points, cursor = trail.since(cursor)
    assert (reset, points) == (False, [[0.15, 0.0]])


def test_a_jump_restarts_the_trail_and_pages_replace_theirs():
    trail = Trail()
    trail.add(0.0, 0.0)
    trail.add(0.1, 0.0)
    _, _, cursor = trail.since(None)
    trail.add(0.1 + TRAIL_JUMP_M, 0.0)
    assert trail.since(cursor)[:2] == (True, [[0.6, 0.0]])


def test_the_trail_keeps_its_newest_points_and_a_page_too_far_behind_gets_them_all():
    trail = Trail()
    _, _, cursor = trail.since(None)
    for i in range(TRAIL_MAX_POINTS + 5):
        trail.add(i * 0.03, 0.0)
    reset, points, _ = trail.since(cursor)
    assert reset and len(points) == TRAIL_MAX_POINTS and points[-1] == [round((TRAIL_MAX_POINTS + 4) * 0.03, 3), 0.0]


def test_the_lidars_offset_is_found_through_the_fixed_transforms():
    transforms = {"base_link": ("base_footprint", Pose2D(0.0, 0.0, 0.0)),
                  "base_scan": ("base_link", Pose2D(-0.064, 0.0, 0.0)),
                  "camera_link": ("base_link", Pose2D(0.064, -0.065, 0.0))}
    assert sensor_offset(transforms, "base_footprint", "base_scan") == Pose2D(-0.064, 0.0, 0.0)
    assert sensor_offset(transforms, "base_footprint", "base_footprint") == Pose2D(0.0, 0.0, 0.0)
    assert sensor_offset(transforms, "base_footprint", "imu_link") is None
    assert sensor_offset({"a": ("b", ORIGIN), "b": ("a", ORIGIN)}, "base_footprint", "a") is None   # a loop


FLOOR_SCENE = [{"kind": "FilledPolygon", "rings": [[[-4, -4], [4, -4], [4, 4], [-4, 4]]], "rgb": [255, 255, 0]},
               {"kind": "Text", "text": "A", "position": [1, 1], "height": 0.2, "angle_deg": 0, "bold": False,
                "rgb": [0, 0, 0]}]


def test_the_scene_primitives_widen_the_world_bounds_to_the_floor():
    primitives = scene_primitives(json.dumps(FLOOR_SCENE))
    assert primitives == FLOOR_SCENE
    world = with_scene_bounds(world_content([marker("robots", CUBE, text="tb3")]), primitives)
    assert "scene" not in world and world["bounds"] == [-4.5, -4.5, 4.5, 4.5]


def test_walls_keep_the_bounds_they_give_when_the_floor_is_smaller():
    walls = world_content([marker("static", LINE_LIST, points=[(-6, 0), (6, 0)])])
    assert with_scene_bounds(walls, FLOOR_SCENE)["bounds"] == [-6.5, -4.5, 6.5, 4.5]


@pytest.mark.parametrize("text", ["not json", "{}", "[1, 2]", json.dumps([{"rgb": [0, 0, 0]}])])
def test_a_scene_that_is_not_a_list_of_primitives_is_ignored(text):
    assert scene_primitives(text) is None
    assert with_scene_bounds(world_content([]), None) == world_content([])
