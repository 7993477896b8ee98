"""The 2.5D camera: Gazebo's camera_info numbers, pixel-exact projection, occlusion, depth, colours, orientation."""

import math

import cv2
import numpy as np
import pytest

from tb3_sim.core.camera import (
    CLIP_FAR_M,
    CLIP_NEAR_M,
    CameraIntrinsics,
    CameraRenderer,
    CameraScene,
    project_point,
)
from tb3_sim.core.turtlebot3 import WAFFLE_R200

MOUNT_M = 0.113
SKY = (200, 200, 220)
FLOOR = (90, 90, 90)
SMALL = CameraIntrinsics(640, 480, 1.3439)
WAFFLE_R200_INTRINSICS = CameraIntrinsics.of(WAFFLE_R200)
RED, BLUE, GREEN, YELLOW = (255, 0, 0), (0, 0, 255), (0, 255, 0), (255, 255, 0)
PILLAR_RADIUS_M = 0.05
PILLAR_HEIGHT_M = 0.5
# Colour difference that tells an object's pixel from the grey floor and sky.
OBJECT_CONTRAST = 40


def renderer(intrinsics=SMALL, **kwargs):
    return CameraRenderer(intrinsics, MOUNT_M, FLOOR, SKY, **kwargs)


def scene(segments=(), segment_heights=(), segment_colours=(), circles=(), circle_heights=(), circle_colours=()):
    return CameraScene(segments, segment_heights, segment_colours, circles, circle_heights, circle_colours)


def pillar(x, y, colour=RED, radius=PILLAR_RADIUS_M, height=PILLAR_HEIGHT_M):
    return scene(circles=[(x, y, radius)], circle_heights=[height], circle_colours=[colour])


def box_edges(x0, y0, x1, y1):
    return [(x0, y0, x1, y0), (x1, y0, x1, y1), (x1, y1, x0, y1), (x0, y1, x0, y0)]


def red_mask(rgb):
    """Pixels whose colour is far from grey in the red direction."""
    return rgb[..., 0].astype(int) - rgb[..., 1] > OBJECT_CONTRAST


def ray_circle_depth(intrinsics, column, cx, cy, r):
    """Depth (along the optical axis) where column's ray from the origin, looking along +x, first meets the circle."""
    slope = (intrinsics.cx - column) / intrinsics.fx
    a, b, c = 1 + slope ** 2, cx + cy * slope, cx ** 2 + cy ** 2 - r ** 2
    disc = b * b - a * c
    return (b - math.sqrt(disc)) / a if disc >= 0 else math.inf


def ray_segment_depth(intrinsics, column, segment):
    slope = (intrinsics.cx - column) / intrinsics.fx
    (x1, y1, x2, y2), direction = segment, np.array([1.0, slope])
    edge = np.array([x2 - x1, y2 - y1])
    matrix = np.column_stack([direction, -edge])
    if abs(np.linalg.det(matrix)) < 1e-12:
        return math.inf
    s, t = np.linalg.solve(matrix, [x1, y1])
    return s if s > 0 and 0 <= t <= 1 else math.inf


# --- camera_info ---------------------------------------------------------------------------------------------------

def test_camera_info_of_the_waffle_r200_at_1920x1080():
    info = WAFFLE_R200_INTRINSICS
    assert (info.width, info.height, info.hfov_rad) == (1920, 1080, 1.3439)
    assert info.fx == pytest.approx(1206.8897719532354) and info.fy == info.fx
    assert (info.cx, info.cy) == (960.5, 540.5)
    assert info.k() == pytest.approx((1206.8897719532354, 0, 960.5, 0, 1206.8897719532354, 540.5, 0, 0, 1))
    assert info.p() == pytest.approx((1206.8897719532354, 0, 960.5, -84.48228403672648,
                                      0, 1206.8897719532354, 540.5, 0, 0, 0, 1, 0))


def test_camera_info_at_640x480_without_baseline():
    assert SMALL.fx == pytest.approx(402.2965906510784)
    assert (SMALL.cx, SMALL.cy) == (320.5, 240.5)
    assert SMALL.p()[3] == 0.0
    assert len(SMALL.k()) == 9 and len(SMALL.p()) == 12


@pytest.mark.parametrize("args", [(0, 480, 1.0), (640, -1, 1.0), (640.5, 480, 1.0), (640, 480, 0.0),
                                  (640, 480, math.pi)])
def test_invalid_intrinsics_are_refused(args):
    with pytest.raises(ValueError):
        CameraIntrinsics(*args)


def test_invalid_renderer_settings_are_refused():
    with pytest.raises(ValueError, match="mount_height_m"):
        CameraRenderer(SMALL, 0.0, FLOOR, SKY)
    with pytest.raises(ValueError, match="near < far"):
        CameraRenderer(SMALL, MOUNT_M, FLOOR, SKY, far_clip_m=1.0, near_clip_m=2.0)


def test_scene_rows_must_match():
    with pytest.raises(ValueError, match="one row per shape"):
        scene(circles=[(1, 0, 0.1)], circle_heights=[], circle_colours=[RED])


# --- projection --------------------------------------------------------------------------------------------------

def test_project_point_by_hand():
    assert project_point(SMALL, MOUNT_M, 0, 0, 0, 2.0, 0.0, MOUNT_M) == pytest.approx((320.5, 240.5, 2.0))
    u, v, depth = project_point(SMALL, MOUNT_M, 1.0, 1.0, math.pi / 2, 2.0, 3.0, 0.0)  # 2 m ahead, 1 m to the right
    assert (u, v, depth) == pytest.approx((320.5 + SMALL.fx / 2, 240.5 + SMALL.fy * MOUNT_M / 2, 2.0))
    assert math.isnan(project_point(SMALL, MOUNT_M, 0, 0, 0, -1.0, 0.0, 0.0)[0])


@pytest.mark.parametrize("bearing", [0.0, 0.25, -0.25, 0.55, -0.55])
@pytest.mark.parametrize("distance", [1.0, 2.5])
def test_pillar_lands_where_camera_info_says(bearing, distance):
    cam_x, cam_y, cam_yaw = 1.0, -2.0, 0.7
    px, py = cam_x + distance * math.cos(cam_yaw + bearing), cam_y + distance * math.sin(cam_yaw + bearing)
    rgb = renderer(WAFFLE_R200_INTRINSICS).render(cam_x, cam_y, cam_yaw, pillar(px, py)).rgb
    columns = np.flatnonzero(red_mask(rgb).any(axis=0))
    info = WAFFLE_R200_INTRINSICS
    spread = math.asin(PILLAR_RADIUS_M / distance)
    assert columns[0] == pytest.approx(info.cx - info.fx * math.tan(bearing + spread), abs=1)
    assert columns[-1] == pytest.approx(info.cx - info.fx * math.tan(bearing - spread), abs=1)
    # Rows in the column of the pillar's centre: top and foot of the surface that column's ray meets.
    centre_u, _, _ = project_point(info, MOUNT_M, cam_x, cam_y, cam_yaw, px, py, 0.0)
    column = round(centre_u)
    depth = ray_circle_depth(info, column, distance * math.cos(bearing), distance * math.sin(bearing),
                             PILLAR_RADIUS_M)
    rows = np.flatnonzero(red_mask(rgb)[:, column])
    top = info.cy - info.fy * (PILLAR_HEIGHT_M - MOUNT_M) / depth
    foot = info.cy + info.fy * MOUNT_M / depth
    assert rows[0] == pytest.approx(max(0, top), abs=1)
    assert rows[-1] == pytest.approx(min(info.height - 1, foot), abs=1)


@pytest.mark.parametrize("bearing, left_half", [(0.3, True), (-0.3, False)])
def test_an_object_to_the_robots_left_appears_on_the_left(bearing, left_half):
    rgb = renderer().render(0, 0, 0, pillar(2 * math.cos(bearing), 2 * math.sin(bearing))).rgb
    columns = np.flatnonzero(red_mask(rgb).any(axis=0))
    assert len(columns)
    assert (columns.max() < SMALL.width / 2) if left_half else (columns.min() > SMALL.width / 2)


# --- occlusion ---------------------------------------------------------------------------------------------------

def test_short_box_hides_only_the_bottom_of_a_tall_wall():
    wall = (3.0, -2.0, 3.0, 2.0)
    box = box_edges(0.85, -0.15, 1.15, 0.15)
    box_height, wall_height = 0.3, 1.0
    world = scene([wall, *box], [wall_height] + [box_height] * 4, [BLUE] + [RED] * 4)
    rgb = renderer().render(0, 0, 0, world).rgb
    column = round(SMALL.cx)
    wall_top = SMALL.cy - SMALL.fy * (wall_height - MOUNT_M) / 3.0
    box_top = SMALL.cy - SMALL.fy * (box_height - MOUNT_M) / 0.85
    box_foot = SMALL.cy + SMALL.fy * MOUNT_M / 0.85
    pixels = rgb[:, column].astype(int)
    is_blue = (pixels[:, 2] - pixels[:, 0] > OBJECT_CONTRAST)
    is_red = (pixels[:, 0] - pixels[:, 2] > OBJECT_CONTRAST)
    assert is_blue[math.ceil(wall_top) + 1:math.floor(box_top) - 1].all()
    assert is_red[math.ceil(box_top) + 1:math.floor(box_foot) - 1].all()
    assert not is_blue[math.ceil(box_top) + 1:].any()
    assert not (is_blue | is_red)[:math.floor(wall_top) - 1].any()
    assert (rgb[math.ceil(box_foot) + 1:, column] == FLOOR).all()


def test_the_top_of_a_box_lower_than_the_camera_shows():
    height = 0.05
    box = box_edges(1.0, -0.2, 1.3, 0.2)
    rgb = renderer().render(0, 0, 0, scene(box, [height] * 4, [RED] * 4)).rgb
    rows = np.flatnonzero(red_mask(rgb)[:, round(SMALL.cx)])
    back_top = SMALL.cy + SMALL.fy * (MOUNT_M - height) / 1.3
    front_foot = SMALL.cy + SMALL.fy * MOUNT_M / 1.0
    assert rows[0] == pytest.approx(back_top, abs=1) and rows[-1] == pytest.approx(front_foot, abs=1)
    assert len(rows) == rows[-1] - rows[0] + 1


def test_objects_behind_the_camera_are_not_drawn():
    behind = scene([(-1.0, -3.0, -1.0, 3.0)], [2.0], [BLUE], [(-2.0, 0.0, 0.5)], [1.0], [RED])
    cam = renderer()
    assert (cam.render(0, 0, 0, behind).rgb == cam.render(0, 0, 0, CameraScene.empty()).rgb).all()


# --- background and depth ----------------------------------------------------------------------------------------

def test_an_empty_scene_is_floor_and_sky():
    frame = renderer().render(3.0, -1.0, 2.0, CameraScene.empty(), depth=True)
    floor_row = math.ceil(SMALL.cy + SMALL.fy * MOUNT_M / CLIP_FAR_M)
    assert (frame.rgb[:floor_row] == SKY).all() and (frame.rgb[floor_row:] == FLOOR).all()
    assert np.isnan(frame.depth[:floor_row]).all() and np.isfinite(frame.depth[floor_row:]).all()
    bottom = SMALL.height - 1
    assert frame.depth[bottom] == pytest.approx(MOUNT_M * SMALL.fy / (bottom - SMALL.cy), rel=1e-6)


def test_depth_along_the_horizon_is_the_distance_along_the_optical_axis():
    room = [*box_edges(-3.0, -2.0, 4.0, 2.5), (1.0, -1.5, 2.5, -0.2)]
    circle = (2.0, 0.8, 0.3)
    world = scene(room, [1.0] * 5, [GREEN] * 5, [circle], [0.4], [RED])
    depth = renderer().render(0, 0, 0, world, depth=True).depth
    row = math.floor(SMALL.cy)
    expected = [min(min(ray_segment_depth(SMALL, j, s) for s in room), ray_circle_depth(SMALL, j, *circle))
                for j in range(SMALL.width)]
    np.testing.assert_allclose(depth[row], expected, rtol=1e-5)


def test_depth_is_nan_in_the_sky_and_outside_the_band():
    world = scene([(6.0, -5.0, 6.0, 0.0), (0.35, 0.05, 0.35, 0.5)], [0.3, 0.3], [BLUE, RED])
    cam = renderer(depth_min_m=WAFFLE_R200.depth_range_m[0], depth_max_m=WAFFLE_R200.depth_range_m[1])
    depth = cam.render(0, 0, 0, world, depth=True).depth
    horizon = math.floor(SMALL.cy)
    assert np.isnan(depth[0]).all()
    assert np.isnan(depth[horizon + 5, -1])  # the far wall, 6 m away
    assert np.isnan(depth[horizon + 5, 0])  # the near wall, 0.35 m away
    floor_depth = MOUNT_M * SMALL.fy / (np.arange(SMALL.height) - SMALL.cy)
    in_band = (floor_depth > WAFFLE_R200.depth_range_m[0]) & (floor_depth < WAFFLE_R200.depth_range_m[1])
    column = round(SMALL.cx)
    np.testing.assert_allclose(depth[in_band, column], floor_depth[in_band], rtol=1e-6)
    assert np.isnan(depth[~in_band, column]).all()


def test_near_clip_and_far_clip():
    wall = scene([(0.5, -1.0, 0.5, 1.0)], [1.0], [BLUE])  # fills the whole view when drawn

    def blue_pixels(cam):
        rgb = cam.render(0, 0, 0, wall).rgb.astype(int)
        return (rgb[..., 2] - rgb[..., 0] > OBJECT_CONTRAST).sum()

    assert blue_pixels(renderer(near_clip_m=CLIP_NEAR_M)) > SMALL.width * SMALL.height / 2
    assert blue_pixels(renderer(near_clip_m=0.6)) == 0
    assert blue_pixels(renderer(far_clip_m=0.4)) == 0


# --- colour ------------------------------------------------------------------------------------------------------

@pytest.mark.parametrize("distance", [0.3, 1.0, 2.0, 4.0])
@pytest.mark.parametrize("yaw", [0.0, 1.6, 3.2, 4.8])
def test_a_red_pillar_segments_as_red_in_hsv(distance, yaw):
    radius = 0.1
    centre = distance + radius
    world = pillar(centre * math.cos(yaw), centre * math.sin(yaw), radius=radius)
    rgb = renderer().render(0, 0, yaw, world).rgb
    hsv = cv2.cvtColor(rgb, cv2.COLOR_RGB2HSV)
    red = cv2.inRange(hsv, (0, 120, 70), (10, 255, 255)) | cv2.inRange(hsv, (170, 120, 70), (179, 255, 255))
    pillar_pixels = red_mask(rgb)
    assert pillar_pixels.sum() > 0
    assert (red[pillar_pixels] == 255).all()
    assert not red[~pillar_pixels].any()


@pytest.mark.parametrize("colour", [GREEN, BLUE, YELLOW])
def test_shading_keeps_hues(colour):
    rgb = renderer().render(0, 0, 0, pillar(2.0, 0.0, colour=colour, radius=0.4)).rgb
    hue = cv2.cvtColor(np.array([[colour]], dtype=np.uint8), cv2.COLOR_RGB2HSV)[0, 0, 0]
    hsv = cv2.cvtColor(rgb, cv2.COLOR_RGB2HSV)
    pixels = hsv[(rgb != SKY).any(axis=2) & (rgb != FLOOR).any(axis=2)]
    assert len(pixels) and (np.abs(pixels[:, 0].astype(int) - hue) <= 1).all()
    assert pixels[:, 2].min() >= 0.5 * 255


def test_rendering_is_deterministic_and_frames_are_independent():
    world = scene(box_edges(1.0, -0.5, 1.5, 0.5), [0.4] * 4, [RED] * 4, [(2.0, 1.0, 0.2)], [0.5], [GREEN])
    cam = renderer()
    first, second = cam.render(0.1, 0.2, 0.3, world, depth=True), cam.render(0.1, 0.2, 0.3, world, depth=True)
    np.testing.assert_array_equal(first.rgb, second.rgb)
    np.testing.assert_array_equal(first.depth, second.depth)
    first.rgb[:] = 0
    assert second.rgb.any()
    assert second.rgb.dtype == np.uint8 and second.rgb.shape == (SMALL.height, SMALL.width, 3)
    assert second.depth.dtype == np.float32 and cam.render(0, 0, 0, world).depth is None
