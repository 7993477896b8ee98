"""The camera sees a world's floor layer: markings where the projection puts them, continuous thin lines, the floor's
depth, occlusion by objects, Gazebo's lit colours, and colours that survive the compressed image's JPEG."""

import math

import cv2
import numpy as np
import pytest

from tb3_sim.core.camera import CameraIntrinsics, CameraRenderer, CameraScene, project_point
from tb3_sim.core.floor import Floor, FloorImage
from tb3_sim.core.materials import FLOOR_RGB, SKY_RGB
from tb3_sim.core.turtlebot3 import WAFFLE_R200
from tb3_sim.core.world import World
from tb3_sim.core.world_file import parse_world
from tb3_sim.ros.outputs.camera import JPEG_QUALITY, RGB_TOPIC, CameraOutput, FloorTextures
from tb3_sim.ros.robot_naming import RobotNaming
from tb3_sim.view import floor_raster
from tb3_sim.view.floor_raster import floor_texture

MOUNT_M = WAFFLE_R200.height_m
SMALL = CameraIntrinsics(640, 480, 1.3439)
FULL_HD = CameraIntrinsics.of(WAFFLE_R200)
# Dark enough to be the black marking on the lit white floor (230).
DARK = 115
# The ordinary OpenCV HSV ranges a student picks for magenta and yellow (H in 0..179).
PINK_HSV = ((140, 100, 100), (170, 255, 255))
YELLOW_HSV = ((20, 100, 100), (40, 255, 255))


def floor_renderer(markings, intrinsics=SMALL, floor=None, **depth_band):
    """A renderer seeing a white 6 x 8 m floor ahead (or `floor`) with `markings` (world-file mappings)."""
    world = parse_world({"name": "w", "floor": floor or {"size": [6, 8], "center": [2.5, 0], "color": "white",
                                                         "markings": markings}})
    camera = CameraRenderer(intrinsics, MOUNT_M, FLOOR_RGB, SKY_RGB, **depth_band)
    camera.use_floor(floor_texture(world.floor))
    return camera


def test_floor_colours_are_the_file_colours_lit_as_gazebo_lights_the_course_floors():
    camera = floor_renderer([{"type": "rectangle", "center": [1.0, 0.0], "size": [0.6, 0.6], "color": "#ff00ff"}],
                            floor={"size": [6, 8], "center": [2.5, 0], "color": "#ffff00", "markings": [
                                {"type": "rectangle", "center": [1.0, 0.0], "size": [0.6, 0.6], "color": "#ff00ff"}]})
    rgb = camera.render(0.0, 0.0, 0.0, CameraScene.empty()).rgb
    u, v, _ = project_point(SMALL, MOUNT_M, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0)
    assert tuple(rgb[round(v), round(u)]) == (228, 0, 228)
    assert tuple(rgb[-1, 0]) == (228, 228, 0)


@pytest.mark.parametrize("intrinsics", [SMALL, FULL_HD], ids=["640x480", "1920x1080"])
@pytest.mark.parametrize("distance, bearing_deg", [(0.6, 0), (1.0, 20), (1.5, -25), (2.5, 10), (3.0, -5)])
def test_a_marking_lands_on_the_pixels_the_projection_gives(intrinsics, distance, bearing_deg):
    """A 0.2 m black square at a known place: its first and last dark rows and, on the row of its centre, its
    first and last dark columns are where project_point puts its edges, within 1 px."""
    half = 0.1
    cx, cy = distance * math.cos(math.radians(bearing_deg)), distance * math.sin(math.radians(bearing_deg))
    camera = floor_renderer([{"type": "rectangle", "center": [cx, cy], "size": [2 * half, 2 * half],
                              "color": "black"}], intrinsics)
    dark = camera.render(0.0, 0.0, 0.0, CameraScene.empty()).rgb[..., 0] < DARK

    def pixel(x, y):
        return project_point(intrinsics, MOUNT_M, 0.0, 0.0, 0.0, x, y, 0.0)[:2]

    rows = np.flatnonzero(dark.any(axis=1))
    # The far edge's row is the top of the square, the near edge's the bottom; pixel centres are integers, so the
    # first dark row is the first whose centre lies past the edge.
    assert rows[0] == pytest.approx(pixel(cx + half, cy)[1], abs=1.0)
    assert rows[-1] == pytest.approx(pixel(cx - half, cy)[1], abs=1.0)
    row = round(pixel(cx, cy)[1])
    columns = np.flatnonzero(dark[row])
    # On that row the floor lies at depth cx; the square's sides y = cy +- half project there.
    depth = (MOUNT_M * intrinsics.fy) / (row - intrinsics.cy)
    assert columns[0] == pytest.approx(intrinsics.cx - intrinsics.fx * (cy + half) / depth, abs=1.0)
    assert columns[-1] == pytest.approx(intrinsics.cx - intrinsics.fx * (cy - half) / depth, abs=1.0)


def test_a_5_cm_line_1_m_ahead_is_continuous_across_the_image():
    """A 5 cm pink line across the view 1 m ahead: every column shows it, in a band as thick as projected."""
    camera = floor_renderer([{"type": "polyline", "points": [[1.0, -3.0], [1.0, 3.0]], "width": 0.05,
                              "color": "#ff00ff"}], FULL_HD)
    rgb = camera.render(0.0, 0.0, 0.0, CameraScene.empty()).rgb
    pink = (rgb[..., 0] > 150) & (rgb[..., 1] < 80)
    per_column = pink.sum(axis=0)
    near, far = (project_point(FULL_HD, MOUNT_M, 0, 0, 0, x, 0.0, 0.0)[1] for x in (0.975, 1.025))
    assert per_column.min() >= math.floor(near - far) - 1
    assert per_column.max() <= math.ceil(near - far) + 1


def test_a_line_along_the_view_is_continuous_into_the_distance():
    camera = floor_renderer([{"type": "polyline", "points": [[0.2, 0.3], [5.4, 0.3]], "width": 0.05,
                              "color": "black"}], FULL_HD)
    dark = camera.render(0.0, 0.0, 0.0, CameraScene.empty()).rgb[..., 0] < DARK
    first, last = (round(project_point(FULL_HD, MOUNT_M, 0, 0, 0, x, 0.3, 0.0)[1]) for x in (5.0, 0.5))
    assert dark[first:last + 1].any(axis=1).all()


def test_depth_below_the_horizon_is_the_floor_distance_and_nan_beyond_the_floor():
    camera = floor_renderer([], FULL_HD, floor={"size": [4.0, 4.0], "color": "white"}, depth_min_m=0.4,
                            depth_max_m=5.0)
    frame = camera.render(0.0, 0.0, 0.0, CameraScene.empty(), depth=True)
    for x in (0.5, 1.0, 1.5, 1.9):
        row = round(project_point(FULL_HD, MOUNT_M, 0, 0, 0, x, 0.0, 0.0)[1])
        expected = MOUNT_M * FULL_HD.fy / (row - FULL_HD.cy)
        assert frame.depth[row, ::97] == pytest.approx(expected, rel=1e-5)
    beyond = round(project_point(FULL_HD, MOUNT_M, 0, 0, 0, 3.0, 0.0, 0.0)[1])
    assert np.isnan(frame.depth[beyond, FULL_HD.width // 2])
    # Beyond the floor rectangle the camera sees Gazebo's background grey.
    assert tuple(frame.rgb[beyond, FULL_HD.width // 2]) == SKY_RGB


def test_an_object_in_front_of_a_marking_hides_it():
    red_disc = [{"type": "circle", "center": [2.0, 0.0], "radius": 0.3, "color": "red"}]
    wall = CameraScene([(1.0, -1.0, 1.0, 1.0)], [0.5], [(0, 0, 255)], np.empty((0, 3)), [], np.empty((0, 3)))
    camera = floor_renderer(red_disc)
    u, v, _ = project_point(SMALL, MOUNT_M, 0, 0, 0, 2.0, 0.0, 0.0)
    open_view = camera.render(0.0, 0.0, 0.0, CameraScene.empty(), depth=True)
    assert tuple(open_view.rgb[round(v), round(u)]) == (228, 0, 0)
    hidden = camera.render(0.0, 0.0, 0.0, wall, depth=True)
    red = (hidden.rgb[..., 0] > 150) & (hidden.rgb[..., 2] < 80)
    assert not red.any()
    assert hidden.rgb[round(v), round(u), 2] > 100   # the blue wall, shaded
    assert hidden.depth[round(v), round(u)] == pytest.approx(1.0, abs=1e-3)
    # Below the wall's foot the floor shows again.
    below_foot = round(project_point(SMALL, MOUNT_M, 0, 0, 0, 0.8, 0.0, 0.0)[1])
    assert tuple(hidden.rgb[below_foot, round(u)]) == (228, 228, 228)


def _segment(rgb, hsv_range):
    hsv = cv2.cvtColor(rgb, cv2.COLOR_RGB2HSV)
    return cv2.inRange(hsv, np.array(hsv_range[0]), np.array(hsv_range[1])) > 0


def test_a_pink_line_on_yellow_segments_with_ordinary_hsv_ranges_after_jpeg():
    """The line_following case: the compressed image's JPEG (quality 80, as published) keeps the line and the floor
    apart with the HSV ranges a student picks."""
    floor = {"size": [8, 8], "color": "#ffff00", "markings": [
        {"type": "curve", "points": [[0.3, -0.5], [1.0, -0.4], [1.2, 0.4], [2.5, 0.5]], "width": 0.15,
         "color": "#ff00ff"}]}
    rgb = floor_renderer([], FULL_HD, floor=floor).render(0.0, 0.0, 0.0, CameraScene.empty()).rgb
    ok, jpeg = cv2.imencode(".jpg", cv2.cvtColor(rgb, cv2.COLOR_RGB2BGR), [cv2.IMWRITE_JPEG_QUALITY, JPEG_QUALITY])
    decoded = cv2.cvtColor(cv2.imdecode(jpeg, cv2.IMREAD_COLOR), cv2.COLOR_BGR2RGB)
    raw_pink, raw_yellow = _segment(rgb, PINK_HSV), _segment(rgb, YELLOW_HSV)
    pink, yellow = _segment(decoded, PINK_HSV), _segment(decoded, YELLOW_HSV)
    assert raw_pink.sum() > 10000
    assert (pink & raw_pink).sum() / (pink | raw_pink).sum() > 0.95
    # Away from the line's antialiased edge, neither colour is taken for the other.
    kernel = np.ones((5, 5), dtype=np.uint8)
    inner_pink, inner_yellow = (cv2.erode(mask.astype(np.uint8), kernel) > 0 for mask in (raw_pink, raw_yellow))
    assert not (pink & inner_yellow).any() and not (yellow & inner_pink).any()
    assert (yellow & raw_yellow).sum() / raw_yellow.sum() > 0.98


def test_a_floor_image_shows_where_it_is_placed():
    pixels = np.zeros((2, 2, 3), dtype=np.uint8)
    pixels[0, :] = (255, 0, 0)     # top row: +y half
    pixels[1, :] = (0, 0, 255)
    floor = Floor((6.0, 6.0), (0.0, 0.0), (255, 255, 255), FloorImage("<test>", pixels, (1.0, 0.0), (1.0, 1.0), 0.0))
    camera = CameraRenderer(SMALL, MOUNT_M, FLOOR_RGB, SKY_RGB)
    camera.use_floor(floor_texture(floor))
    rgb = camera.render(0.0, 0.0, 0.0, CameraScene.empty()).rgb
    left = project_point(SMALL, MOUNT_M, 0, 0, 0, 1.0, 0.35, 0.0)
    right = project_point(SMALL, MOUNT_M, 0, 0, 0, 1.0, -0.35, 0.0)
    assert tuple(rgb[round(left[1]), round(left[0])]) == (228, 0, 0)
    assert tuple(rgb[round(right[1]), round(right[0])]) == (0, 0, 228)


def test_without_a_floor_layer_the_ground_plane_stays_flat():
    camera = CameraRenderer(SMALL, MOUNT_M, FLOOR_RGB, SKY_RGB)
    rgb = camera.render(0.0, 0.0, 0.0, CameraScene.empty()).rgb
    assert (rgb[-1] == FLOOR_RGB).all()


def test_the_robots_camera_output_shows_the_worlds_floor_layer():
    world = World(parse_world({"name": "w", "floor": {"size": [4, 4], "color": "#ffff00"}}))
    camera = CameraOutput(world.robot, RobotNaming(), WAFFLE_R200, 320, 180)
    reading = camera.read(world, 0.0, {RGB_TOPIC})
    assert tuple(reading.rgb[-1, 160]) == (228, 228, 0)


def test_the_floor_texture_built_at_world_load_is_the_one_every_camera_uses(monkeypatch):
    world = World(parse_world({"name": "w", "floor": {"size": [4, 4], "color": "#ffff00"}}))
    textures = FloorTextures()
    textures.prepare(world.description.floor)
    built = textures.of(world.description.floor)   # waits for the build the world load started
    monkeypatch.setattr(floor_raster, "floor_texture", lambda floor: pytest.fail("rasterised again"))
    assert textures.of(world.description.floor) is built and textures.of(None) is None
    for _ in range(2):
        camera = CameraOutput(world.robot, RobotNaming(), WAFFLE_R200, 320, 180, floor_textures=textures)
        assert tuple(camera.read(world, 0.0, {RGB_TOPIC}).rgb[-1, 160]) == (228, 228, 0)
