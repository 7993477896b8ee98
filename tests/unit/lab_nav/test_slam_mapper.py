"""The SLAM loop: gmapping's processing and map-publication rules, the odometry correction, odd scans."""
import math

import numpy as np
import pytest

from lab_nav.slam import LaserScanData, Slam, SlamError, params_from_dict
from lab_nav.slam import pose as poses

TB3_PARAMS = {"map_update_interval": 2.0, "maxUrange": 3.0, "minimumScore": 50, "linearUpdate": 1.0,
              "angularUpdate": 0.2, "temporalUpdate": 0.5, "xmin": -10.0, "ymin": -10.0, "xmax": 10.0,
              "ymax": 10.0, "particles": 100}
LASER_ON_BASE = (-0.064, 0.0, 0.0)


def _scan(room, stamp, base_pose, ranges=None):
    laser = poses.compose(base_pose, LASER_ON_BASE)
    return LaserScanData(stamp, room.ranges(laser) if ranges is None else ranges, 0.0, 6.28319 / 359, 0.12, 3.5)


def _slam(**overrides):
    return Slam(params_from_dict({**TB3_PARAMS, **overrides}))


def test_the_first_scan_is_processed_and_its_map_is_due_at_once(room):
    slam = _slam()
    outcome = slam.add_scan(_scan(room, 10.0, (0, 0, 0)), (0, 0, 0), LASER_ON_BASE)
    assert outcome.processed and outcome.map_due
    values, geometry = slam.occupancy()
    assert values.shape == (384, 384) and (geometry.origin_x, geometry.origin_y) == (-10.0, -10.0)
    assert set(np.unique(values)) == {-1, 0, 100}


def test_a_standing_robot_is_processed_every_temporal_update_and_mapped_every_map_update_interval(room):
    slam = _slam()
    stamps = 10.0 + 0.2 * np.arange(16)  # 5 Hz for 3 s
    outcomes = [slam.add_scan(_scan(room, t, (0, 0, 0)), (0, 0, 0), LASER_ON_BASE) for t in stamps]
    processed = [round(t, 1) for t, o in zip(stamps, outcomes) if o.processed]
    maps = [round(t, 1) for t, o in zip(stamps, outcomes) if o.map_due]
    assert processed == [10.0, 10.6, 11.2, 11.8, 12.4, 13.0]   # more than 0.5 s after the last one
    assert maps == [10.0, 12.4]                                 # more than 2.0 s after the last map


def test_without_temporal_update_a_standing_robot_is_never_processed_again(room):
    slam = _slam(temporalUpdate=-1.0)
    outcomes = [slam.add_scan(_scan(room, 10 + 0.2 * i, (0, 0, 0)), (0, 0, 0), LASER_ON_BASE) for i in range(30)]
    assert [o.processed for o in outcomes] == [True] + [False] * 29


def test_travel_and_rotation_trigger_processing(room):
    slam = _slam(temporalUpdate=-1.0)
    slam.add_scan(_scan(room, 0.0, (0, 0, 0)), (0, 0, 0), LASER_ON_BASE)
    moved = [slam.add_scan(_scan(room, 0.2 * i, (0.25 * i, 0, 0)), (0.25 * i, 0, 0), LASER_ON_BASE).processed
             for i in range(1, 5)]
    assert moved == [False, False, False, True]
    turned = [slam.add_scan(_scan(room, 1 + 0.2 * i, (1.0, 0, 0.07 * i)), (1.0, 0, 0.07 * i),
                            LASER_ON_BASE).processed for i in range(1, 4)]
    assert turned == [False, False, True]


def test_throttle_scans_looks_at_every_nth_scan_only(room):
    slam = _slam(throttle_scans=3, temporalUpdate=0.0)
    outcomes = [slam.add_scan(_scan(room, 0.2 * i, (0, 0, 0)), (0, 0, 0), LASER_ON_BASE) for i in range(7)]
    assert [o.processed for o in outcomes] == [True, False, False, True, False, False, True]


def test_a_clock_jumping_back_restarts_the_timing_and_keeps_the_map(room):
    slam = _slam()
    for i in range(20):
        slam.add_scan(_scan(room, 100 + 0.2 * i, (0, 0, 0)), (0, 0, 0), LASER_ON_BASE)
    mapped = (slam.occupancy()[0] == 100).sum()
    outcome = slam.add_scan(_scan(room, 0.2, (0, 0, 0)), (0, 0, 0), LASER_ON_BASE)
    assert outcome.clock_jumped_back and outcome.processed and outcome.map_due
    assert (slam.occupancy()[0] == 100).sum() >= 0.95 * mapped


def test_scans_with_inf_nan_and_short_ranges_are_used_without_the_bad_beams(room):
    slam = _slam()
    ranges = room.ranges(LASER_ON_BASE)
    ranges[::3], ranges[1::7], ranges[2::11] = np.nan, -np.inf, 0.05
    outcome = slam.add_scan(_scan(room, 1.0, (0, 0, 0), ranges), (0, 0, 0), LASER_ON_BASE)
    assert outcome.processed
    all_bad = np.full(360, np.nan)
    assert slam.add_scan(_scan(room, 2.0, (0, 0, 0), all_bad), (0, 0, 0), LASER_ON_BASE).processed


def test_the_matcher_corrects_drifting_odometry(room):
    """Odometry with 5 % scale error and 3 deg/m heading drift on a 6 m drive: the SLAM pose stays within a few
    cm of the truth while the odometry ends tens of cm off, and the map's walls are where the room's are."""
    slam = _slam()
    truth = odom = (-2.0, -1.5, 0.0)
    route = [(0.1, 0.0)] * 30 + [(0.0, 0.2)] * 8 + [(0.1, 0.0)] * 25 + [(0.0, 0.2)] * 8 + [(0.1, 0.0)] * 10
    worst = 0.0
    for i, (step, turn) in enumerate(route):
        truth = poses.compose(truth, (step, 0.0, turn))
        odom = poses.compose(odom, (step * 1.05, 0.0, turn + math.radians(3) * step))
        slam.add_scan(_scan(room, 0.2 * i, truth), odom, LASER_ON_BASE)
        estimate = slam.map_pose(odom)
        worst = max(worst, math.hypot(estimate[0] - truth[0], estimate[1] - truth[1]))
    assert math.hypot(odom[0] - truth[0], odom[1] - truth[1]) > 0.25
    assert worst < 0.06
    values, geometry = slam.occupancy()
    rows, cols = np.nonzero(values == 100)
    xs, ys = geometry.cell_center(cols, rows)
    assert np.mean(room.wall_distance(xs, ys) <= 0.1) >= 0.95


@pytest.mark.parametrize("params, problem", [
    ({"delta": 0}, "~delta must be > 0"),
    ({"particles": "many"}, "~particles must be a finite number"),
    ({"xmin": 5.0, "xmax": 1.0}, "~xmin must be less than ~xmax"),
    ({"occ_thresh": 1.5}, "~occ_thresh must be in [0, 1)"),
    ({"base_frame": "base link"}, "~base_frame must be a frame name"),
    ({"maxUrange": -1}, "~maxUrange must be > 0"),
])
def test_bad_params_name_the_parameter(params, problem):
    with pytest.raises(SlamError, match=problem.replace("[", r"\[").replace("(", r"\(").replace(")", r"\)")):
        params_from_dict(params)


def test_unknown_params_are_ignored_and_frames_lose_a_leading_slash():
    params = params_from_dict({"delta_l": 3, "base_frame": "/base_footprint"})
    assert params.base_frame == "base_footprint" and params.tf_delay == params.transform_publish_period
    assert params.ranges_for(3.5) == (3.49, 3.49)


def test_a_teleport_leaves_the_scans_across_the_jump_out_and_keeps_the_map(room):
    slam = _slam(temporalUpdate=0.0)
    for i in range(5):
        slam.add_scan(_scan(room, 0.2 * i, (-2.0, -1.5, 0.0)), (-2.0, -1.5, 0.0), LASER_ON_BASE)
    # TF interpolates the odometry of the scan taken across the jump: half way, where the robot never was.
    halfway, target = (-0.5, -0.5, 0.5), (1.0, 0.5, 1.0)
    outcomes = [slam.add_scan(_scan(room, 1.0, halfway), halfway, LASER_ON_BASE),
                slam.add_scan(_scan(room, 1.2, target), target, LASER_ON_BASE),
                slam.add_scan(_scan(room, 1.4, target), target, LASER_ON_BASE),
                slam.add_scan(_scan(room, 1.6, target), target, LASER_ON_BASE)]
    assert [o.odometry_jumped for o in outcomes] == [True, True, False, False]
    assert [o.processed for o in outcomes] == [False, False, False, True]
    estimate = slam.map_pose(target)
    assert math.hypot(estimate[0] - target[0], estimate[1] - target[1]) < 0.05
