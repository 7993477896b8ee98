"""A synthetic room for the SLAM tests: walls as segments and an exact 360-beam LiDAR (TB3's angles, no noise)."""
import numpy as np
import pytest

from lab_nav.slam.beams import scan_beams

BEAMS = 360
ANGLE_INCREMENT = 6.28319 / (BEAMS - 1)
RANGE_MIN, RANGE_MAX = 0.12, 3.5
WALL_SHIFT_M = (0.013, 0.021)


def _room_segments():
    """An L-shaped 6 x 5 m room with a pillar box and a short wall, so no direction is ambiguous (m)."""
    outline = [(-3, -2.5), (3, -2.5), (3, 1.0), (1.5, 1.0), (1.5, 2.5), (-3, 2.5)]
    segments = [(outline[i], outline[(i + 1) % len(outline)]) for i in range(len(outline))]
    box = [(0.4, -0.8), (0.9, -0.8), (0.9, -0.3), (0.4, -0.3)]
    segments += [(box[i], box[(i + 1) % 4]) for i in range(4)]
    segments.append(((-2.0, 0.8), (-1.0, 1.6)))
    # Walls off the 0.05 m cell boundaries, as real walls are: a wall on a boundary biases a match by half a cell.
    return np.array(segments, dtype=float) + WALL_SHIFT_M


class Room:
    segments = _room_segments()

    def ranges(self, laser_pose, max_range=RANGE_MAX):
        """True ranges of the beams of a laser at `laser_pose` (x, y, yaw); +inf beyond max_range."""
        x, y, yaw = laser_pose
        angles = yaw + ANGLE_INCREMENT * np.arange(BEAMS)
        d = np.column_stack((np.cos(angles), np.sin(angles)))[:, None, :]
        a, b = self.segments[None, :, 0, :], self.segments[None, :, 1, :]
        e = b - a
        w = a - np.array([x, y])
        denom = d[..., 0] * e[..., 1] - d[..., 1] * e[..., 0]
        with np.errstate(divide="ignore", invalid="ignore"):
            t = (w[..., 0] * e[..., 1] - w[..., 1] * e[..., 0]) / denom
            u = (w[..., 0] * d[..., 1] - w[..., 1] * d[..., 0]) / denom
        t = np.where((np.abs(denom) > 1e-12) & (t > 0) & (u >= 0) & (u <= 1), t, np.inf)
        ranges = t.min(axis=1)
        return np.where((ranges >= RANGE_MIN) & (ranges < max_range), ranges, np.inf)

    def beams(self, laser_pose, max_urange=3.0):
        """The scan from `laser_pose` as the SLAM uses it (lab_nav.slam.beams.Beams, laser frame)."""
        return scan_beams(self.ranges(laser_pose), 0.0, ANGLE_INCREMENT, RANGE_MIN, RANGE_MAX, RANGE_MAX - 0.01,
                          max_urange)

    def hit_points(self, laser_pose):
        beams = self.beams(laser_pose)
        return beams.ends[beams.hit]

    def wall_distance(self, xs, ys):
        """Distance (m) from each point to the nearest wall."""
        p = np.column_stack((xs, ys))[:, None, :]
        a, b = self.segments[None, :, 0, :], self.segments[None, :, 1, :]
        e = b - a
        t = np.clip(((p - a) * e).sum(-1) / (e * e).sum(-1), 0, 1)
        return np.linalg.norm(a + t[..., None] * e - p, axis=-1).min(axis=1)


@pytest.fixture
def room():
    return Room()
