"""The opt-in odometry error: scale and heading drift per metre, seeded noise, jumps replayed exactly, off by
default."""
import math

import pytest

from tb3_sim.core.errors import ConfigError
from tb3_sim.core.geometry import Pose2D
from tb3_sim.core.odometry_error import DriftingOdometry, OdometryErrorModel
from tb3_sim.core.world_file import SHIPPED_WORLDS_DIR
from tb3_sim.ros.config import config_from_params


def _drive_straight(odometry, metres, steps=100):
    pose = None
    for i in range(steps + 1):
        pose = odometry.pose(Pose2D(metres * i / steps, 0.0, 0.0))
    return pose


def test_scale_error_overstates_distance():
    pose = _drive_straight(DriftingOdometry(OdometryErrorModel(scale_error=0.02), seed=0), 2.0)
    assert (pose.x, pose.y, pose.yaw) == pytest.approx((2.04, 0.0, 0.0))


def test_heading_drift_turns_per_metre_travelled():
    pose = _drive_straight(DriftingOdometry(OdometryErrorModel(heading_drift=math.radians(1)), seed=0), 3.0)
    assert pose.yaw == pytest.approx(math.radians(3))
    assert pose.y > 0.02


def test_noise_is_seeded():
    model = OdometryErrorModel(heading_noise=0.05)
    first, again, other = (_drive_straight(DriftingOdometry(model, seed), 2.0) for seed in (1, 1, 2))
    assert first == again and first != other


def test_a_jump_is_replayed_exactly_and_the_error_is_kept():
    odometry = DriftingOdometry(OdometryErrorModel(scale_error=0.1), seed=0)
    _drive_straight(odometry, 1.0)
    odometry.jumped()
    pose = odometry.pose(Pose2D(-2.0, 3.0, 1.0))
    assert (pose.x, pose.y, pose.yaw) == pytest.approx((-1.9, 3.0, 1.0))


def test_off_by_default_and_bad_values_are_named():
    config = config_from_params({}, SHIPPED_WORLDS_DIR)
    assert not config.odometry_error.enabled
    assert config_from_params({"odom_scale_error": 0.02}, SHIPPED_WORLDS_DIR).odometry_error.scale_error == 0.02
    with pytest.raises(ConfigError, match="~odom_scale_error must be <= 0.5"):
        config_from_params({"odom_scale_error": 2.0}, SHIPPED_WORLDS_DIR)
    with pytest.raises(ConfigError, match="~odom_heading_noise must be >= 0"):
        config_from_params({"odom_heading_noise": -1.0}, SHIPPED_WORLDS_DIR)

