"""Grid cells along laser rays, for the obstacle layer's clearing (free space between the sensor and a hit)."""
import numpy as np


def cells_along(geometry, origin_xy, ends_xy):
    """(cols, rows) of the in-grid cells the segments from origin_xy to each end point pass, ends included.

    Sampled every half cell along each segment, which visits the cells a Bresenham line would (and a few
    corner-touching neighbours). origin_xy is (2,), ends_xy (N, 2), both in m in the grid's frame.
    """
    ends = np.asarray(ends_xy, dtype=float).reshape(-1, 2)
    if ends.size == 0:
        return np.zeros(0, int), np.zeros(0, int)
    origin = np.asarray(origin_xy, dtype=float)
    lengths = np.linalg.norm(ends - origin, axis=1)
    steps = int(np.ceil(lengths.max() / (0.5 * geometry.resolution))) + 1
    t = np.linspace(0.0, 1.0, steps)
    points = origin + t[None, :, None] * (ends - origin)[:, None, :]
    cols, rows = geometry.world_to_cell(points[..., 0].ravel(), points[..., 1].ravel())
    inside = geometry.contains(cols, rows)
    return cols[inside], rows[inside]
