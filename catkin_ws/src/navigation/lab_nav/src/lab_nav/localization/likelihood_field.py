"""amcl's likelihood-field laser model: how probable a scan is from a pose, given the map.

The map's occupied cells (>= 65, amcl's occupancy threshold, i.e. map_server's 100) make a distance field
capped at laser_likelihood_max_dist; off-map points count as that distance. Each used beam (every
n-th of the scan so that at most laser_max_beams remain, readings at or beyond the max range or non-finite left
out) ends at a distance z from the nearest obstacle, and scores
pz = z_hit * exp(-z^2 / (2 sigma_hit^2)) + z_rand / max_range. The pose's weight factor is 1 + sum(pz^3): amcl's
own ad hoc combination (not a product), which keeps a filter with hundreds of beams from collapsing on one
particle.
"""
from dataclasses import dataclass

import numpy as np
from scipy import ndimage

OCCUPIED_THRESHOLD = 65


@dataclass(frozen=True)
class LaserParams:
    """amcl's laser model params as turtlebot3's amcl.launch sets them (max_range 3.5 m, 180 beams)."""

    max_beams: int = 180
    max_range: float = 3.5
    min_range: float = -1.0
    z_hit: float = 0.5
    z_rand: float = 0.5
    sigma_hit: float = 0.2
    likelihood_max_dist: float = 2.0


class LikelihoodField:
    """The distance field of one map (geometry: MapGeometry, occupancy: (height, width) int8 data)."""

    def __init__(self, geometry, occupancy, max_dist):
        self.geometry = geometry
        occupied = np.asarray(occupancy).reshape(geometry.height, geometry.width) >= OCCUPIED_THRESHOLD
        if occupied.any():
            distance = ndimage.distance_transform_edt(~occupied) * geometry.resolution
        else:
            distance = np.full(occupied.shape, max_dist)
        self.max_dist = max_dist
        self.distance = np.minimum(distance, max_dist)
        self.free = np.asarray(occupancy).reshape(geometry.height, geometry.width) == 0

        self._scores = {}

    def distance_at(self, x, y):
        cols, rows = self.geometry.world_to_cell(x, y)
        inside = self.geometry.contains(cols, rows)
        out = np.full(np.shape(cols), self.max_dist)
        out[inside] = self.distance[rows[inside], cols[inside]]
        return out

    def beam_scores(self, params, max_range):
        """pz^3 of a beam ending in each cell, in a grid padded by one cell of the value beyond the map (where
        the distance is max_dist); computed once per (z_hit, sigma_hit, z_rand, max_range)."""
        key = (params.z_hit, params.sigma_hit, params.z_rand, max_range)
        if key not in self._scores:
            distance = np.pad(self.distance, 1, constant_values=self.max_dist)
            pz = params.z_hit * np.exp(-(distance * distance) / (2.0 * params.sigma_hit ** 2)) + \
                params.z_rand / max_range
            self._scores[key] = pz ** 3
        return self._scores[key]

    def padded_cells(self, x, y):
        """(rows, cols) of the points in beam_scores' padded grid; points off the map land on its border."""
        g = self.geometry
        cols = np.clip(np.floor((x - g.origin_x) / g.resolution), -1, g.width).astype(np.intp) + 1
        rows = np.clip(np.floor((y - g.origin_y) / g.resolution), -1, g.height).astype(np.intp) + 1
        return rows, cols


def select_beams(ranges, angles, params, range_max):
    """(ranges, angles) of the beams the model uses: every step-th of the scan, valid readings only."""
    ranges, angles = np.asarray(ranges, dtype=float), np.asarray(angles, dtype=float)
    step = max(1, (len(ranges) - 1) // max(params.max_beams - 1, 1)) if params.max_beams > 1 else len(ranges)
    ranges, angles = ranges[::step], angles[::step]
    max_range = params.max_range if params.max_range > 0 else range_max
    ok = np.isfinite(ranges) & (ranges < max_range)
    if params.min_range > 0:
        ok &= ranges >= params.min_range
    return ranges[ok], angles[ok]


def weights(field, poses, laser_pose, ranges, angles, params, max_range):
    """(N,) weight factors of particles `poses` (N, 3) for the selected beams; laser_pose (x, y, yaw) is the
    laser in the base frame, max_range (m) the range z_rand is spread over."""
    lx, ly, lyaw = laser_pose
    c, s = np.cos(poses[:, 2]), np.sin(poses[:, 2])
    sx = poses[:, 0] + c * lx - s * ly
    sy = poses[:, 1] + s * lx + c * ly
    # cos/sin of (particle yaw + beam angle) by the angle-sum identities: two outer products instead of N x M
    # trigonometric calls; the beam's score is looked up per cell (the map's pz^3 computed once)
    bc, bs = ranges * np.cos(lyaw + angles), ranges * np.sin(lyaw + angles)
    ex = sx[:, None] + np.outer(c, bc) - np.outer(s, bs)
    ey = sy[:, None] + np.outer(s, bc) + np.outer(c, bs)
    rows, cols = field.padded_cells(ex, ey)
    return 1.0 + field.beam_scores(params, max_range)[rows, cols].sum(axis=1)
