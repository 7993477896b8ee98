"""The scan matcher finds a scan's pose in a map from a guess that is off by 0.2 m and 10 degrees."""
import math

import numpy as np
import pytest

from lab_nav.slam.grid import SlamGrid, initial_geometry
from lab_nav.slam.matcher import ScanMatcher


def _mapped_room(room, poses):
    grid = SlamGrid(initial_geometry(-10, -10, 10, 10, 0.05))
    for x, y, yaw in poses:
        beams = room.beams((x, y, yaw))
        c, s = math.cos(yaw), math.sin(yaw)
        ends = np.column_stack((x + c * beams.ends[:, 0] - s * beams.ends[:, 1],
                                y + s * beams.ends[:, 0] + c * beams.ends[:, 1]))
        grid.integrate((x, y), ends, beams.hit)
    return grid


@pytest.mark.parametrize("offset", [(0.2, 0.0, math.radians(10)), (-0.14, 0.14, -math.radians(10)),
                                    (0.0, -0.2, math.radians(5))])
def test_recovers_a_known_offset_of_0_2_m_and_10_degrees(room, offset):
    grid = _mapped_room(room, [(-1.5, -1.0, 0.0), (0.0, 0.5, 1.0), (1.5, -1.5, 2.0)])
    true_pose = (-0.5, -1.2, 0.3)
    guess = (true_pose[0] + offset[0], true_pose[1] + offset[1], true_pose[2] + offset[2])
    match = ScanMatcher(sigma=0.05, iterations=5).match(grid.occupied(), grid.geometry, room.hit_points(true_pose),
                                                       guess)
    assert match.pose[:2] == pytest.approx(true_pose[:2], abs=0.02)
    assert match.pose[2] == pytest.approx(true_pose[2], abs=math.radians(0.5))
    assert match.score > 0.8 * len(room.hit_points(true_pose))


def test_a_wrong_pose_scores_lower_than_the_right_one(room):
    grid = _mapped_room(room, [(-1.5, -1.0, 0.0)])
    points = room.hit_points((-1.5, -1.0, 0.0))
    matcher = ScanMatcher(sigma=0.05, iterations=0)
    right = matcher.match(grid.occupied(), grid.geometry, points, (-1.5, -1.0, 0.0))
    wrong = matcher.match(grid.occupied(), grid.geometry, points, (-0.5, 0.0, 1.5))
    assert wrong.score < 0.5 * right.score


def test_an_empty_map_returns_the_guess_with_score_zero(room):
    grid = SlamGrid(initial_geometry(-10, -10, 10, 10, 0.05))
    match = ScanMatcher(0.05, 5).match(grid.occupied(), grid.geometry, room.hit_points((0, 0, 0)), (1.0, 2.0, 0.5))
    assert match.pose == (1.0, 2.0, 0.5) and match.score == 0.0
