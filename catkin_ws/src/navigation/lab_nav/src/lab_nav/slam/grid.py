"""The SLAM map: a growing grid of per-cell beam counts and log-odds, laid out as gmapping lays out its map.

Geometry (openslam_gmapping's): storage comes in PATCH_CELLS x PATCH_CELLS patches, so the initial width is the
extent over the resolution, rounded up to whole cells and then down to whole patches (TB3's +-10 m at 0.05 m:
400 -> 384 cells, origin (-10, -10)). When a beam end point or the laser falls outside, that side grows to the
point -/+ GROWTH_MARGIN_M, rounded out to whole patches; the grid never shrinks.

Each cell keeps what gmapping's cells keep - visits (beams that ended in or passed through it) and hits (beams
that ended in it) - and the published value is theirs: -1 never visited, 100 when hits / visits > occ_thresh,
else 0. It also keeps a clamped log-odds sum (LOG_ODDS_HIT per hit, LOG_ODDS_MISS per pass), which the scan
matcher reads as "occupied" where it is > 0: one stray beam through a wall cell does not erase the wall.
"""

import math

import numpy as np

from lab_nav.maps.geometry import MapGeometry

PATCH_CELLS = 32
GROWTH_MARGIN_M = 10.0
LOG_ODDS_HIT = math.log(0.7 / 0.3)
LOG_ODDS_MISS = math.log(0.4 / 0.6)
LOG_ODDS_LIMITS = (-4.0, 4.0)
FREE, OCCUPIED, UNKNOWN = 0, 100, -1
# Free cells along a beam are sampled this many times per cell, so no cell a beam crosses is skipped.
SAMPLES_PER_CELL = 2


def initial_geometry(xmin, ymin, xmax, ymax, delta):
    """gmapping's first map: origin (xmin, ymin), sides of ceil(extent/delta) cells rounded down to patches."""
    def side(extent):
        cells = math.ceil(round(extent / delta, 9))
        return max(PATCH_CELLS, cells // PATCH_CELLS * PATCH_CELLS)
    return MapGeometry(delta, side(xmax - xmin), side(ymax - ymin), float(xmin), float(ymin))


def grown_geometry(geometry, xs, ys):
    """The geometry grown (whole patches, GROWTH_MARGIN_M beyond the farthest point) to hold every (x, y); the
    same object when they all fit. Returns (geometry, (cols added on the low side, rows added on the low side))."""
    patch_m = PATCH_CELLS * geometry.resolution

    def grow(origin, cells, values):
        low_add = high_add = 0
        end = origin + cells * geometry.resolution
        if values.min() < origin:
            low_add = math.ceil((origin - (values.min() - GROWTH_MARGIN_M)) / patch_m) * PATCH_CELLS
        if values.max() >= end:
            high_add = math.ceil((values.max() + GROWTH_MARGIN_M - end) / patch_m) * PATCH_CELLS
        return origin - low_add * geometry.resolution, cells + low_add + high_add, low_add

    xs, ys = np.asarray(xs, dtype=float), np.asarray(ys, dtype=float)
    origin_x, width, col_shift = grow(geometry.origin_x, geometry.width, xs)
    origin_y, height, row_shift = grow(geometry.origin_y, geometry.height, ys)
    if (col_shift, row_shift, width, height) == (0, 0, geometry.width, geometry.height):
        return geometry, (0, 0)
    return MapGeometry(geometry.resolution, width, height, origin_x, origin_y), (col_shift, row_shift)


class SlamGrid:
    """Beam counts and log-odds on a growing grid; arrays are indexed [row, col] (y, x) as OccupancyGrid."""

    def __init__(self, geometry):
        self.geometry = geometry
        shape = (geometry.height, geometry.width)
        self.visits = np.zeros(shape, dtype=np.int32)
        self.hits = np.zeros(shape, dtype=np.int32)
        self.log_odds = np.zeros(shape, dtype=np.float32)

    def integrate(self, laser_xy, ends_xy, hit):
        """Add one scan: beams from the laser position `laser_xy` (map frame, m) to `ends_xy` (N x 2); `hit[i]`
        marks a beam that ended on an obstacle (the others were cut at maxUrange and only pass through)."""
        ends_xy = np.asarray(ends_xy, dtype=float).reshape(-1, 2)
        hit = np.asarray(hit, dtype=bool)
        self._grow(np.append(ends_xy[:, 0], laser_xy[0]), np.append(ends_xy[:, 1], laser_xy[1]))
        if not len(ends_xy):
            return
        passed_cols, passed_rows = self._passed_cells(np.asarray(laser_xy, dtype=float), ends_xy, hit)
        hit_cols, hit_rows = self.geometry.world_to_cell(ends_xy[hit, 0], ends_xy[hit, 1])
        # Count on the scan's bounding box only: a scan touches a few metres of a map that may be much larger.
        all_cols, all_rows = np.append(passed_cols, hit_cols), np.append(passed_rows, hit_rows)
        col0, row0 = all_cols.min(), all_rows.min()
        box = (all_rows.max() - row0 + 1, all_cols.max() - col0 + 1)
        passes = np.bincount((passed_rows - row0) * box[1] + passed_cols - col0, minlength=box[0] * box[1])
        ends = np.bincount((hit_rows - row0) * box[1] + hit_cols - col0, minlength=box[0] * box[1])
        window = np.s_[row0:row0 + box[0], col0:col0 + box[1]]
        self.visits[window] += (passes + ends).reshape(box).astype(np.int32)
        self.hits[window] += ends.reshape(box).astype(np.int32)
        log_odds = self.log_odds[window]
        log_odds += (passes * LOG_ODDS_MISS + ends * LOG_ODDS_HIT).reshape(box).astype(np.float32)
        np.clip(log_odds, *LOG_ODDS_LIMITS, out=log_odds)

    def occupancy(self, occ_thresh):
        """int8 array [row, col] of -1 / 0 / 100 as gmapping publishes its cells."""
        values = np.full(self.visits.shape, UNKNOWN, dtype=np.int8)
        seen = self.visits > 0
        values[seen] = FREE
        values[seen & (self.hits > occ_thresh * self.visits)] = OCCUPIED
        return values

    def occupied(self):
        """Boolean array of cells the scan matcher treats as obstacles (log-odds > 0)."""
        return self.log_odds > 0.0

    def _passed_cells(self, start, ends, hit):
        """(cols, rows) of the cells each beam passes through, once per beam, without a hit beam's end cell."""
        geometry = self.geometry
        lengths = np.hypot(*(ends - start).T)
        samples = int(np.ceil(lengths.max() / geometry.resolution * SAMPLES_PER_CELL)) + 1
        fractions = np.linspace(0.0, 1.0, samples)
        xs = start[0] + np.outer(ends[:, 0] - start[0], fractions)
        ys = start[1] + np.outer(ends[:, 1] - start[1], fractions)
        cols, rows = geometry.world_to_cell(xs, ys)
        flat = rows * geometry.width + cols
        keep = ~(hit[:, None] & (flat == flat[:, -1:]))
        beam = np.broadcast_to(np.arange(len(ends))[:, None], flat.shape)
        cells = geometry.width * geometry.height
        flat = np.unique(beam[keep].astype(np.int64) * cells + flat[keep]) % cells
        return flat % geometry.width, flat // geometry.width

    def _grow(self, xs, ys):
        geometry, (col_shift, row_shift) = grown_geometry(self.geometry, xs, ys)
        if geometry is self.geometry:
            return
        for name in ("visits", "hits", "log_odds"):
            old = getattr(self, name)
            new = np.zeros((geometry.height, geometry.width), dtype=old.dtype)
            new[row_shift:row_shift + old.shape[0], col_shift:col_shift + old.shape[1]] = old
            setattr(self, name, new)
        self.geometry = geometry
