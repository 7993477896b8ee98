"""nav_goals.closest_clearance_m on synthetic Waffle scans of a wall ahead: the LiDAR's 0.01 m noise does not turn a
clear pass into a contact, and a wall at the body is still one."""
import math

import numpy as np

from roslab import nav_goals

BEAMS = 360
NOISE_M = 0.01
WAFFLE_FRONT_M = 0.077   # the footprint's front edge ahead of base_footprint


def wall_scans(clearance_m, count, seed=0):
    """`count` scans (the probe's dicts) of a wall across x at `clearance_m` ahead of the Waffle's front edge."""
    rng = np.random.default_rng(seed)
    angles = np.arange(BEAMS) * 2 * math.pi / BEAMS
    wall_x = WAFFLE_FRONT_M + clearance_m - nav_goals.WAFFLE_SCAN_X_M   # in base_scan's frame
    with np.errstate(divide="ignore"):
        ranges = np.where(np.cos(angles) > 0.05, wall_x / np.cos(angles), np.inf)
    ranges = np.where(ranges < 3.5, ranges, np.inf)
    return [{"ranges": list(ranges + rng.normal(0.0, NOISE_M, BEAMS)), "angle_min": 0.0,
             "angle_increment": 2 * math.pi / BEAMS} for _ in range(count)]


def test_a_wall_0_04_m_clear_is_not_measured_as_a_contact_over_a_hundred_noisy_scans():
    """The worst case: the wall parallel to the body's flat front, so ~90 beams read the same clearance."""
    assert nav_goals.closest_clearance_m(wall_scans(0.04, 100)) > 0.02


def test_a_wall_at_the_body_measures_about_zero():
    assert abs(nav_goals.closest_clearance_m(wall_scans(0.0, 20))) < 0.02


def test_nothing_seen_is_infinitely_clear():
    assert nav_goals.closest_clearance_m([{"ranges": [math.inf] * BEAMS, "angle_min": 0.0,
                                           "angle_increment": 2 * math.pi / BEAMS}]) == math.inf
