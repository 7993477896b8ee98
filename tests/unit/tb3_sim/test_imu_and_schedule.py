"""IMU readings from ground truth, the drift-free schedule, and the pose helpers."""

import math

import pytest

from tb3_sim.core.geometry import Pose2D, Twist2D, quaternion_to_yaw, wrap_angle, yaw_to_quaternion
from tb3_sim.core.imu import Imu
from tb3_sim.core.schedule import PeriodicSchedule
from tb3_sim.core.world import PHYSICS_STEP_S, World
from tb3_sim.core.world_file import WorldDescription


def test_imu_reports_spawn_yaw_and_zero_acceleration_at_rest():
    world = World(WorldDescription("empty"), robot_pose=Pose2D(0.0, 0.0, 0.8))
    imu = Imu()
    readings = []
    for _ in range(3):
        world.run(0.02)
        readings.append(imu.read(world.time_s, world.robot.pose, world.robot.twist_world))
    assert all(r.yaw == pytest.approx(0.8) and r.accel_x == 0.0 and r.accel_y == 0.0 for r in readings)


def test_imu_acceleration_is_in_the_body_frame_without_gravity():
    world = World(WorldDescription("empty"), robot_pose=Pose2D(0.0, 0.0, math.pi / 2))
    world.robot.set_command(0.26, 0.0)
    imu = Imu()
    imu.read(world.time_s, world.robot.pose, world.robot.twist_world)
    world.run(0.2)
    reading = imu.read(world.time_s, world.robot.pose, world.robot.twist_world)
    assert reading.accel_x == pytest.approx(1.0, abs=1e-3), "the 1 m/s² rim ramp, straight ahead"
    assert reading.accel_y == pytest.approx(0.0, abs=1e-3)
    assert reading.time_s == world.time_s


def test_imu_yaw_rate():
    world = World(WorldDescription("empty"))
    world.robot.set_command(0.0, 1.5)
    world.run(1.0)
    reading = Imu().read(world.time_s, world.robot.pose, world.robot.twist_world)
    assert reading.yaw_rate == pytest.approx(1.5, abs=1e-4)


def test_imu_does_not_difference_across_a_gap():
    imu = Imu(max_gap_s=0.015)
    imu.read(1.0, Pose2D(), Twist2D(0.0, 0.0, 0.0))
    assert imu.read(1.01, Pose2D(), Twist2D(0.1, 0.0, 0.0)).accel_x == pytest.approx(10.0)
    assert imu.read(2.0, Pose2D(), Twist2D(0.3, 0.0, 0.0)).accel_x == 0.0, "a second without readings"
    assert imu.read(2.01, Pose2D(), Twist2D(0.31, 0.0, 0.0)).accel_x == pytest.approx(1.0)


def test_schedule_averages_exactly_its_rate_on_a_coarser_step():
    schedule = PeriodicSchedule(30.0)
    fired = [i * PHYSICS_STEP_S for i in range(1, 2001) if schedule.due(i * PHYSICS_STEP_S)]
    assert len(fired) == 300
    gaps = {round(b - a, 6) for a, b in zip(fired, fired[1:])}
    assert gaps <= {0.03, 0.035}


def test_schedule_rebases_instead_of_bursting():
    schedule = PeriodicSchedule(5.0)
    assert schedule.due(10.0)
    assert not schedule.due(10.1)
    assert schedule.due(10.2)


def test_schedule_rate_zero_fires_every_time():
    schedule = PeriodicSchedule(0.0)
    assert all(schedule.due(t) for t in (0.0, 0.0, 0.001))


def test_pose_and_quaternion_helpers():
    assert Pose2D(1.0, 2.0, math.pi / 2).compose(1.0, 0.0) == pytest.approx((1.0, 3.0))
    assert Twist2D(1.0, 0.0, 0.3).rotated(math.pi / 2) == pytest.approx((0.0, 1.0, 0.3))
    assert wrap_angle(3 * math.pi / 2) == pytest.approx(-math.pi / 2)
    assert wrap_angle(-math.pi) == math.pi
    for yaw in (-3.0, -0.5, 0.0, 1.0, 3.1):
        assert quaternion_to_yaw(*yaw_to_quaternion(yaw)) == pytest.approx(yaw)
