"""Grid cells along laser rays, for the obstacle layer's clearing (free space between the sensor and a hit)."""
import numpy as np

SAMPLES_PER_CELL = 2
"""Points sampled along a ray per cell length: every half cell visits the cells a Bresenham line would (and a
few corner-touching neighbours)."""


def _inside_grid(geometry, origin, offsets):
    """(t0, t1): the part of each segment origin + t * offset, 0 <= t <= 1, inside the grid's rectangle (empty
    where t0 > t1), by clipping against each axis' slab (Liang-Barsky)."""
    t0, t1 = np.zeros(len(offsets)), np.ones(len(offsets))
    low = (geometry.origin_x, geometry.origin_y)
    high = (low[0] + geometry.width * geometry.resolution, low[1] + geometry.height * geometry.resolution)
    for axis in (0, 1):
        d = offsets[:, axis]
        with np.errstate(divide="ignore", invalid="ignore"):
            a = (low[axis] - origin[axis]) / d
            b = (high[axis] - origin[axis]) / d
        parallel = d == 0.0
        outside = parallel & ((origin[axis] < low[axis]) | (origin[axis] >= high[axis]))
        t0 = np.where(parallel, t0, np.maximum(t0, np.minimum(a, b)))
        t1 = np.where(parallel, t1, np.minimum(t1, np.maximum(a, b)))
        t1 = np.where(outside, -1.0, t1)
    return t0, t1


def cells_along(geometry, origin_xy, ends_xy):
    """(cols, rows) of the in-grid cells the segments from origin_xy to each end point pass, ends included.

    Each segment is cut to the grid first and sampled SAMPLES_PER_CELL times per cell of its own length, so a
    short ray costs few points. origin_xy is (2,), ends_xy (N, 2), both in m in the grid's frame.
    """
    ends = np.asarray(ends_xy, dtype=float).reshape(-1, 2)
    origin = np.asarray(origin_xy, dtype=float)
    offsets = ends - origin
    t0, t1 = _inside_grid(geometry, origin, offsets)
    keep = t1 >= t0
    if not keep.any():
        return np.zeros(0, int), np.zeros(0, int)
    t0, t1, offsets = t0[keep], t1[keep], offsets[keep]
    lengths = (t1 - t0) * np.linalg.norm(offsets, axis=1)
    counts = np.ceil(lengths * SAMPLES_PER_CELL / geometry.resolution).astype(int) + 1
    ray = np.repeat(np.arange(len(counts)), counts)
    step = np.arange(counts.sum()) - np.repeat(np.cumsum(counts) - counts, counts)
    t = t0[ray] + (t1 - t0)[ray] * step / np.maximum(counts - 1, 1)[ray]
    cols, rows = geometry.world_to_cell(origin[0] + t * offsets[ray, 0], origin[1] + t * offsets[ray, 1])
    inside = geometry.contains(cols, rows)
    return cols[inside], rows[inside]
