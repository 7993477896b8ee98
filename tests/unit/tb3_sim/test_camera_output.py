"""The camera output: Gazebo's R200 topics and encodings, laziness, what it shows where the projection says,
and the static TF chain to its optical frame (fake publishers, no master)."""
import math
from dataclasses import replace

import cv2
import numpy as np
import pytest

from tb3_sim.core.camera import project_point
from tb3_sim.core.geometry import Pose2D
from tb3_sim.core.lidar import cast_rays
from tb3_sim.core.model_xml import parse_model_xml
from tb3_sim.core.turtlebot3 import WAFFLE, WAFFLE_R200
from tb3_sim.core.world import World
from tb3_sim.core.world_file import WorldDescription, load_world, shipped_world_path
from tb3_sim.ros.outputs import OutputPublisher
from tb3_sim.ros.outputs.camera import (
    COMPRESSED_TOPIC,
    DEPTH_INFO_TOPIC,
    DEPTH_TOPIC,
    RGB_INFO_TOPIC,
    RGB_TOPIC,
    CameraOutput,
)
from tb3_sim.ros.robot_naming import RobotNaming

WIDTH, HEIGHT = 320, 180
IMAGE_TOPICS = {RGB_TOPIC, COMPRESSED_TOPIC, DEPTH_TOPIC}
RED_BOX_SDF = """<sdf version="1.6"><model name="red_box"><static>true</static><link name="link">
  <collision name="c"><geometry><box><size>0.3 0.3 0.4</size></box></geometry></collision>
  <visual name="v"><geometry><box><size>0.3 0.3 0.4</size></box></geometry>
    <material><script><uri>file://media/materials/scripts/gazebo.material</uri><name>Gazebo/Red</name></script>
    </material></visual></link></model></sdf>"""


class FakePublisher:
    def __init__(self, subscribers):
        self.subscribers = subscribers

    def get_num_connections(self):
        return self.subscribers


class CountingRenderer:
    """Wraps the real renderer and records each call's depth flag."""

    def __init__(self, renderer):
        self.renderer = renderer
        self.calls = []

    def render(self, x, y, yaw, scene, depth=False):
        self.calls.append(depth)
        return self.renderer.render(x, y, yaw, scene, depth=depth)


def waffle_camera(world):
    """The camera output of the world's Waffle, at WIDTH x HEIGHT, topics relative to the node."""
    return CameraOutput(world.robot, RobotNaming(), WAFFLE_R200, WIDTH, HEIGHT)


def camera_messages(world, subscribed):
    """One frame's messages {topic: message} with subscribers on `subscribed`, and the renderer's calls."""
    camera = waffle_camera(world)
    camera.renderer = CountingRenderer(camera.renderer)
    publisher = OutputPublisher([camera], lambda topic: FakePublisher(int(topic.name in subscribed)))
    names = {id(pub): name for name, pub in publisher.publishers.items()}
    messages = {}
    for _ in range(round(1.0 / 30.0 / world.step_s) + 1):
        world.step()
        for pub, message in publisher.collect(world):
            messages[names[id(pub)]] = message
    return messages, camera.renderer.calls


def world_with_red_box(x=1.5, y=0.0):
    world = World(WorldDescription("empty"))
    spec = parse_model_xml(RED_BOX_SDF)
    world.spawn_model(replace(spec, pose=Pose2D(x, y, 0.0)))
    return world


def test_topics_encodings_frames_and_camera_info():
    messages, _ = camera_messages(world_with_red_box(), IMAGE_TOPICS | {RGB_INFO_TOPIC, DEPTH_INFO_TOPIC})
    rgb, depth, compressed = messages[RGB_TOPIC], messages[DEPTH_TOPIC], messages[COMPRESSED_TOPIC]
    assert (rgb.encoding, rgb.width, rgb.height, rgb.step, len(rgb.data)) == ("rgb8", WIDTH, HEIGHT, 3 * WIDTH,
                                                                              3 * WIDTH * HEIGHT)
    assert (depth.encoding, depth.step) == ("32FC1", 4 * WIDTH)
    assert compressed.format == "rgb8; jpeg compressed bgr8"
    decoded = cv2.imdecode(np.frombuffer(compressed.data, np.uint8), cv2.IMREAD_COLOR)
    assert decoded.shape == (HEIGHT, WIDTH, 3)
    for message in messages.values():
        assert message.header.frame_id == "camera_rgb_optical_frame"
        assert message.header.stamp.to_sec() == pytest.approx(rgb.header.stamp.to_sec())
    info = messages[RGB_INFO_TOPIC]
    fx = WIDTH / (2.0 * math.tan(1.3439 / 2.0))
    assert (info.width, info.height, info.distortion_model) == (WIDTH, HEIGHT, "plumb_bob")
    assert list(info.D) == [0.0] * 5
    assert list(info.K) == pytest.approx([fx, 0, (WIDTH + 1) / 2, 0, fx, (HEIGHT + 1) / 2, 0, 0, 1])
    assert info.P[0] == pytest.approx(fx) and info.P[2] == pytest.approx((WIDTH + 1) / 2)
    assert messages[DEPTH_INFO_TOPIC].K == info.K


def test_nothing_is_rendered_without_an_image_subscriber():
    messages, calls = camera_messages(world_with_red_box(), set())
    assert messages == {} and calls == []
    messages, calls = camera_messages(world_with_red_box(), {RGB_INFO_TOPIC})
    assert set(messages) == {RGB_INFO_TOPIC} and calls == []


def test_depth_is_rendered_only_while_someone_takes_it():
    _, calls = camera_messages(world_with_red_box(), {COMPRESSED_TOPIC})
    assert calls == [False]
    _, calls = camera_messages(world_with_red_box(), {DEPTH_TOPIC})
    assert calls == [True]


@pytest.mark.parametrize("box_y", [0.0, 0.4, -0.4])
def test_a_gazebo_red_box_is_red_where_the_projection_says(box_y):
    world = world_with_red_box(1.5, box_y)
    messages, _ = camera_messages(world, {RGB_TOPIC, DEPTH_TOPIC})
    image = np.frombuffer(messages[RGB_TOPIC].data, np.uint8).reshape(HEIGHT, WIDTH, 3)
    depth = np.frombuffer(messages[DEPTH_TOPIC].data, np.float32).reshape(HEIGHT, WIDTH)
    intrinsics = waffle_camera(world).intrinsics
    near_face_x = 1.5 - 0.15
    u, v, expected_depth = project_point(intrinsics, WAFFLE_R200.height_m, WAFFLE_R200.x_m, WAFFLE_R200.y_m,
                                         0.0, near_face_x, box_y, 0.2)
    r, g, b = (int(c) for c in image[round(v), round(u)])
    assert r > 100 and g < 30 and b < 30, f"pixel ({u:.0f}, {v:.0f}) is {(r, g, b)}, not red"
    assert depth[round(v), round(u)] == pytest.approx(expected_depth, abs=0.01)
    assert np.isnan(depth[0, round(u)]), "sky above the box has no depth"


def test_static_tf_reaches_the_optical_frame_at_the_camera_mount():
    joints = {child: (parent, xyz, rpy) for parent, child, xyz, rpy in WAFFLE.static_transforms}
    x = y = z = 0.0
    frame = "camera_rgb_optical_frame"
    chain = []
    while frame in joints:
        parent, (dx, dy, dz), _ = joints[frame]
        x, y, z, frame = x + dx, y + dy, z + dz, parent
        chain.append(parent)
    assert chain == ["camera_rgb_frame", "camera_link", "base_link", "base_footprint"]
    assert (x, y, z) == pytest.approx((WAFFLE_R200.x_m, WAFFLE_R200.y_m, WAFFLE_R200.height_m))
    assert joints["camera_rgb_optical_frame"][2] == (-1.57, 0.0, -1.57)


def test_depth_along_the_horizon_equals_the_lidar_style_range_of_each_columns_ray():
    """In turtlebot3_world, the depth image's horizon row is the distance the LiDAR's ray caster finds along
    each column's centre ray, projected on the optical axis."""
    world = World(load_world(shipped_world_path("turtlebot3_world")), Pose2D(-2.0, -0.5, 0.3))
    camera = waffle_camera(world)
    reading = camera.read(world, world.time_s, {DEPTH_TOPIC})
    intrinsics = camera.intrinsics
    pose = world.robot.pose
    x, y = pose.compose(WAFFLE_R200.x_m, WAFFLE_R200.y_m)
    columns = np.arange(0, WIDTH, 7)
    offsets = np.arctan((intrinsics.cx - columns) / intrinsics.fx)
    ranges = cast_rays((x, y), pose.yaw + offsets, world.obstacles(), 0.0, 5.0)
    horizon_row = round(intrinsics.cy)
    seen = np.isfinite(ranges) & (ranges * np.cos(offsets) > 0.45)
    assert seen.sum() > len(columns) // 2
    depth = reading.depth[horizon_row, columns]
    assert depth[seen] == pytest.approx((ranges * np.cos(offsets))[seen], abs=0.01)
