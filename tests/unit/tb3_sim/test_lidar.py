"""LiDAR: Gazebo's beam layout, analytic distances, +inf, the 0.12 m blind zone, noise and seeds."""

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from tb3_sim.core.geometry import Pose2D
from tb3_sim.core.lidar import (
    LIDAR_ANGLE_INCREMENT_RAD,
    LIDAR_NOISE_STDDEV_M,
    LIDAR_RANGE_MAX_M,
    LIDAR_RANGE_MIN_M,
    Lidar,
    beam_angles,
)
from tb3_sim.core.obstacles import Obstacles, static_obstacles
from tb3_sim.core.shapes import Box, Circle, Polygon, Segment
from tb3_sim.core.world import World
from tb3_sim.core.world_file import ModelSpec, WorldDescription

SCAN_OFFSET_M = 0.064
THREE_SIGMA_M = 3 * LIDAR_NOISE_STDDEV_M


def exact_scan(shapes, origin=Pose2D()):
    return Lidar(noise_stddev_m=0.0).scan(origin, static_obstacles(shapes), 0.0).ranges


def wall_world(x, y_half=5.0):
    """A world whose only geometry is a wall along x = `x` from y = -y_half to y_half."""
    return WorldDescription("wall", "wall", (Segment((x, -y_half), (x, y_half)),))


def test_layout_constants_are_gazebos():
    result = Lidar().scan(Pose2D(), Obstacles.empty(), 1.5)
    assert result.angle_min == 0.0 and result.angle_max == 6.28319
    assert result.angle_increment == pytest.approx(6.28319 / 359) and result.angle_increment != 2 * math.pi / 360
    assert (result.range_min, result.range_max) == (0.12, 3.5)
    assert (result.time_increment, result.scan_time) == (0.0, 0.0)
    assert result.time_s == 1.5
    assert result.ranges.dtype == np.float32 and result.ranges.shape == (360,)
    assert beam_angles()[-1] == pytest.approx(6.28319)


def test_nothing_hit_is_inf():
    result = Lidar().read(world := World(WorldDescription("empty")), world.robot, 0.0)
    assert np.all(np.isposinf(result.ranges))


def test_hit_at_or_beyond_range_max_is_inf():
    ranges = exact_scan([Segment((3.5, -1.0), (3.5, 1.0)), Segment((-3.6, -1.0), (-3.6, 1.0))])
    assert np.isposinf(ranges[0]) and np.isposinf(ranges[180])
    assert exact_scan([Segment((3.49, -1.0), (3.49, 1.0))])[0] == pytest.approx(3.49)


@pytest.mark.parametrize("index, approx_deg", [(0, 0.0), (90, 90.25), (180, 180.5), (270, 270.75), (359, 360.0)])
def test_beam_directions_index_0_ahead_and_ccw(index, approx_deg):
    theta = index * LIDAR_ANGLE_INCREMENT_RAD
    assert math.degrees(theta) == pytest.approx(approx_deg, abs=0.01)
    origin = Pose2D(1.0, -2.0, 0.7)
    pillar = Circle(origin.compose(2.0 * math.cos(theta), 2.0 * math.sin(theta)), 0.05)
    ranges = exact_scan([pillar], origin)
    nearest = int(np.argmin(ranges))
    assert nearest == index or {nearest, index} == {0, 359}
    assert ranges[index] == pytest.approx(1.95, abs=0.005)


def test_left_and_right_in_the_robot_frame():
    world = World(WorldDescription("w", "w", (Circle((-SCAN_OFFSET_M, 1.0), 0.1), Circle((-SCAN_OFFSET_M, -2.0), 0.1))))
    ranges = Lidar().read(world, world.robot, world.time_s).ranges
    assert ranges[90] == pytest.approx(0.9, abs=THREE_SIGMA_M)
    assert ranges[270] == pytest.approx(1.9, abs=0.01 + THREE_SIGMA_M)
    assert np.isposinf(ranges[0]) and np.isposinf(ranges[180])


def test_distance_to_a_wall_equals_the_analytic_value():
    world = World(wall_world(2.0))
    ranges = Lidar().read(world, world.robot, world.time_s).ranges.astype(float)
    angles = beam_angles()
    expected = (2.0 + SCAN_OFFSET_M) / np.cos(angles)
    in_range = (np.cos(angles) > 0) & (expected < LIDAR_RANGE_MAX_M - THREE_SIGMA_M)
    assert abs(ranges[0] - 2.064) <= THREE_SIGMA_M
    errors = ranges[in_range] - expected[in_range]
    assert np.all(np.abs(errors) <= 4.5 * LIDAR_NOISE_STDDEV_M)
    assert abs(errors.mean()) < 3 * LIDAR_NOISE_STDDEV_M / math.sqrt(errors.size)
    assert errors.std() == pytest.approx(LIDAR_NOISE_STDDEV_M, rel=0.25)
    out_of_range = (np.cos(angles) <= 0) | (expected > LIDAR_RANGE_MAX_M + THREE_SIGMA_M)
    assert np.all(np.isposinf(ranges[out_of_range]))


def box_face_distance(origin, direction, center, yaw, size):
    """Analytic distance along a ray to a rotated box (slab method in the box frame)."""
    c, s = math.cos(-yaw), math.sin(-yaw)
    px, py = origin[0] - center[0], origin[1] - center[1]
    p = (c * px - s * py, s * px + c * py)
    d = (c * direction[0] - s * direction[1], s * direction[0] + c * direction[1])
    t_near, t_far = -math.inf, math.inf
    for axis, half in ((0, size[0] / 2), (1, size[1] / 2)):
        if d[axis] == 0:
            continue
        t1, t2 = (-half - p[axis]) / d[axis], (half - p[axis]) / d[axis]
        t_near, t_far = max(t_near, min(t1, t2)), min(t_far, max(t1, t2))
    return t_near if LIDAR_RANGE_MIN_M <= t_near <= t_far else math.inf


def test_distance_to_a_rotated_box_equals_the_analytic_value():
    center, yaw, size = (1.5, 0.1), 0.3, (0.4, 0.6)
    world = World(WorldDescription("arena"), robot_pose=Pose2D(0.0, 0.0, 0.0))
    world.spawn_model(ModelSpec("box", Box(*size, 0.5), Pose2D(*center, yaw)))
    ranges = Lidar().read(world, world.robot, world.time_s).ranges
    origin = (-SCAN_OFFSET_M, 0.0)
    checked = 0
    for index, angle in enumerate(beam_angles()):
        expected = box_face_distance(origin, (math.cos(angle), math.sin(angle)), center, yaw, size)
        if math.isinf(expected):
            assert np.isposinf(ranges[index])
        else:
            assert abs(ranges[index] - expected) <= 4.5 * LIDAR_NOISE_STDDEV_M
            checked += 1
    assert abs(ranges[0] - box_face_distance(origin, (1.0, 0.0), center, yaw, size)) <= THREE_SIGMA_M
    assert checked >= 10


def test_nothing_closer_than_range_min_is_seen():
    tiny_pillar = Circle((0.08, 0.0), 0.02)
    ranges = exact_scan([tiny_pillar, Segment((1.0, -1.0), (1.0, 1.0))])
    assert ranges[0] == pytest.approx(1.0), "the beam reports what lies behind the near object"
    assert np.nanmin(ranges) >= LIDAR_RANGE_MIN_M


def test_noisy_readings_are_clamped_to_the_range():
    lidar = Lidar(seed=3, noise_stddev_m=0.05)
    near = static_obstacles([Polygon(((0.121, -0.01), (0.2, -0.01), (0.2, 0.01), (0.121, 0.01)))])
    far = static_obstacles([Segment((3.49, -0.1), (3.49, 0.1))])
    near_readings = [lidar.scan(Pose2D(), near, 0.0).ranges[0] for _ in range(50)]
    far_readings = [lidar.scan(Pose2D(), far, 0.0).ranges[0] for _ in range(50)]
    assert min(near_readings) == np.float32(LIDAR_RANGE_MIN_M)
    assert max(far_readings) == np.float32(LIDAR_RANGE_MAX_M)
    assert all(np.isfinite(far_readings))


def test_same_seed_same_scans_different_seed_different():
    def scans(seed):
        world, lidar = World(wall_world(1.0)), Lidar(seed)
        world.robot.set_command(0.1, 0.3)
        out = []
        for _ in range(3):
            world.run(0.2)
            out.append(lidar.read(world, world.robot, world.time_s).ranges)
        return out

    first, again, other = scans(7), scans(7), scans(8)
    assert all(np.array_equal(a, b) for a, b in zip(first, again))
    assert not np.array_equal(first[0], other[0])


def test_objects_lower_than_the_scan_plane_are_not_seen():
    world = World(WorldDescription("empty"))
    world.spawn_model(ModelSpec("low", Box(0.3, 0.3, 0.1), Pose2D(1.0, 0.0, 0.0)))
    assert np.isposinf(Lidar().read(world, world.robot, world.time_s).ranges[0])
    world.spawn_model(ModelSpec("tall", Box(0.3, 0.3, 0.2), Pose2D(2.0, 0.0, 0.0)))
    ranges = Lidar().read(world, world.robot, world.time_s).ranges
    assert ranges[0] == pytest.approx(2.0 - 0.15 + SCAN_OFFSET_M, abs=THREE_SIGMA_M)
    seeing = World(WorldDescription("empty"))
    seeing.spawn_model(ModelSpec("low", Box(0.3, 0.3, 0.1), Pose2D(1.0, 0.0, 0.0)))
    seen = Lidar(sees_low_objects=True).read(seeing, seeing.robot, 0.0).ranges[0]
    assert seen == pytest.approx(1.0 - 0.15 + SCAN_OFFSET_M, abs=THREE_SIGMA_M)


def test_scan_follows_a_moved_model():
    world = World(WorldDescription("empty"))
    world.spawn_model(ModelSpec("can", Box(0.2, 0.2, 0.5), Pose2D(1.0, 0.0, 0.0)))
    world.set_model_state("can", Pose2D(0.0, 1.0, 0.0))
    ranges = Lidar().read(world, world.robot, world.time_s).ranges
    assert np.isposinf(ranges[0]) and np.isfinite(ranges[90])


@settings(max_examples=60, deadline=None)
@given(distance=st.floats(0.2, 3.3), yaw=st.floats(-math.pi, math.pi), beam=st.integers(0, 359))
def test_noise_free_distance_to_a_facing_wall(distance, yaw, beam):
    """A wall at `distance`, perpendicular to beam `beam`, is seen by that beam at exactly `distance`."""
    origin = Pose2D(0.3, -0.2, yaw)
    theta = yaw + beam * LIDAR_ANGLE_INCREMENT_RAD
    ux, uy = math.cos(theta), math.sin(theta)
    foot = (origin.x + distance * ux, origin.y + distance * uy)
    wall = Segment((foot[0] - uy, foot[1] + ux), (foot[0] + uy, foot[1] - ux))
    assert exact_scan([wall], origin)[beam] == pytest.approx(distance, abs=1e-5)
