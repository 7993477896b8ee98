"""Camera benchmarks for scripts/bench (wall-clock figures; not a test, never asserted).

    source scripts/env.sh && python3 tests/bench/camera_bench.py

Renders frames of the shipped turtlebot3_world (with three coloured boxes spawned) from the launch file's spawn
point through the simulator's own path (world obstacles -> camera scene -> renderer), turning through a full
circle so that every frame sees something different. Each figure is the median over the frames, in
milliseconds of one core:
- one 1920x1080 RGB frame (target <= 25 ms) and its JPEG (RGB to BGR, cv2.imencode quality 80, <= 25 ms);
- one 640x480 RGB frame (<= 4 ms);
- one 1920x1080 RGB + depth frame (<= one 30 Hz frame period);
- one 1920x1080 (<= 30 ms) and one 640x480 (<= 6 ms) RGB frame of a marked floor: an 8 x 8 m yellow floor with a
  15 cm pink track of seven Béziers, end bars, a black border and text (the line_following course floor's
  elements), seen from along the track, its texture built once beforehand.
`run()` returns the rows [(name, value, unit, target, comparison)] for scripts/bench's table.
"""
import math
import statistics
import time

import cv2
import numpy as np

from tb3_sim.core.camera import CameraIntrinsics, CameraRenderer, CameraScene
from tb3_sim.core.geometry import Pose2D
from tb3_sim.core.materials import FLOOR_RGB, SKY_RGB, material_rgb
from tb3_sim.core.shapes import Box
from tb3_sim.core.turtlebot3 import WAFFLE_R200
from tb3_sim.core.world import World
from tb3_sim.core.world_file import ModelSpec, load_world, parse_world, shipped_world_path
from tb3_sim.ros.outputs.camera import camera_scene
from tb3_sim.view.floor_raster import floor_texture

FRAMES = 36
WARM_UP_FRAMES = 3
JPEG_QUALITY = 80
SMALL_WIDTH_PX, SMALL_HEIGHT_PX = 640, 480
R200_FRAME_PERIOD_MS = 1000.0 / WAFFLE_R200.rate_hz
WAFFLE_R200_INTRINSICS = CameraIntrinsics.of(WAFFLE_R200)
SPAWN = Pose2D(-2.0, -0.5, 0.0)
# Boxes: name, centre x, y (m), size x, y, height (m), Gazebo material.
BOXES = [("red", -1.0, -0.6, 0.3, 0.3, 0.3, "Gazebo/Red"), ("blue", 0.6, 0.55, 0.2, 0.4, 0.6, "Gazebo/Blue"),
         ("yellow", -0.55, 0.55, 0.25, 0.25, 0.05, "Gazebo/Yellow")]


def turtlebot3_world_scene():
    """The camera's scene of turtlebot3_world with BOXES spawned, as the simulator builds it."""
    world = World(load_world(shipped_world_path("turtlebot3_world")), SPAWN)
    for name, x, y, size_x, size_y, height, material in BOXES:
        world.spawn_model(ModelSpec(name, Box(size_x, size_y, height), Pose2D(x, y, 0.0), static=True,
                                    rgb=material_rgb(material)))
    return camera_scene(world.obstacles())


def median_ms(work):
    """Median wall time of work(yaw) in ms over FRAMES headings spread around the circle (after a warm-up)."""
    yaws = [2.0 * math.pi * k / FRAMES for k in range(FRAMES)]
    for yaw in yaws[:WARM_UP_FRAMES]:
        work(yaw)
    times = []
    for yaw in yaws:
        start = time.perf_counter()
        work(yaw)
        times.append(time.perf_counter() - start)
    return 1e3 * statistics.median(times)


def render_ms(intrinsics, depth=False):
    renderer = CameraRenderer(intrinsics, WAFFLE_R200.height_m, FLOOR_RGB, SKY_RGB)
    scene = turtlebot3_world_scene()
    return median_ms(lambda yaw: renderer.render(SPAWN.x, SPAWN.y, yaw, scene, depth=depth))


def jpeg_ms():
    renderer = CameraRenderer(WAFFLE_R200_INTRINSICS, WAFFLE_R200.height_m, FLOOR_RGB, SKY_RGB)
    scene = turtlebot3_world_scene()
    frames = {}

    def encode(yaw):
        rgb = frames[yaw]
        cv2.imencode(".jpg", cv2.cvtColor(rgb, cv2.COLOR_RGB2BGR), [cv2.IMWRITE_JPEG_QUALITY, JPEG_QUALITY])

    for k in range(FRAMES):
        yaw = 2.0 * math.pi * k / FRAMES
        frames[yaw] = np.ascontiguousarray(renderer.render(SPAWN.x, SPAWN.y, yaw, scene).rgb)
    return median_ms(encode)


# The line_following track's centreline (course_worlds spec 3.3), metres: start, then control, control, end per piece.
TRACK = [[2.3797, -2.5004], [2.3797, -2.5004], [-1.0369, -2.9464], [-1.9639, -2.5206], [-2.8909, -2.0947],
         [-3.0883, -1.7718], [-3.1155, -1.1670], [-3.1426, -0.5622], [-2.9017, -0.0899], [-2.0447, 0.3483],
         [-1.1877, 0.7864], [1.0529, -0.0693], [1.8747, 0.3079], [2.6964, 0.6850], [2.8410, 0.9429],
         [2.8444, 1.4594], [2.8478, 1.9759], [2.6759, 2.2908], [1.8343, 2.6918], [0.9926, 3.0928],
         [-2.1659, 2.7120], [-2.1659, 2.7120]]
MARKED_FLOOR = {"size": [8, 8], "color": "#ffff00", "markings": [
    {"type": "rectangle", "center": [0, 0], "size": [7.9, 7.9], "width": 0.1, "color": "black"},
    {"type": "curve", "points": TRACK, "width": 0.15, "color": "#ff00ff"},
    {"type": "polyline", "points": [[2.34, -2.84], [2.42, -2.16]], "width": 0.08, "color": "#ff00ff"},
    {"type": "text", "text": "START", "position": [2.578, -2.47], "height": 0.18, "angle_deg": 97, "bold": True,
     "color": "black"}]}
# Along the track from its start, facing -x.
MARKED_VIEW = Pose2D(2.4, -2.5, math.pi)


def marked_floor_ms(intrinsics):
    renderer = CameraRenderer(intrinsics, WAFFLE_R200.height_m, FLOOR_RGB, SKY_RGB)
    renderer.use_floor(floor_texture(parse_world({"name": "marked", "floor": MARKED_FLOOR}).floor))
    scene = CameraScene.empty()
    return median_ms(lambda yaw: renderer.render(MARKED_VIEW.x, MARKED_VIEW.y, MARKED_VIEW.yaw + yaw / 8.0, scene))


def run():
    """[(name, value, unit, target, comparison)] rows; comparison is ">=" or "<=" against target."""
    small = CameraIntrinsics(SMALL_WIDTH_PX, SMALL_HEIGHT_PX, WAFFLE_R200_INTRINSICS.hfov_rad)
    return [
        ("camera: one 1920x1080 RGB render (turtlebot3_world)", render_ms(WAFFLE_R200_INTRINSICS), "ms", 25.0, "<="),
        ("camera: JPEG of that frame (RGB to BGR, imencode q80)", jpeg_ms(), "ms", 25.0, "<="),
        ("camera: one 640x480 RGB render", render_ms(small), "ms", 4.0, "<="),
        ("camera: one 1920x1080 RGB + depth render", render_ms(WAFFLE_R200_INTRINSICS, depth=True), "ms",
         round(R200_FRAME_PERIOD_MS, 1), "<="),
        ("camera: one 1920x1080 RGB render of a marked floor", marked_floor_ms(WAFFLE_R200_INTRINSICS), "ms", 30.0,
         "<="),
        ("camera: one 640x480 RGB render of a marked floor", marked_floor_ms(small), "ms", 6.0, "<="),
    ]


if __name__ == "__main__":
    from report import print_table
    print_table(run())
