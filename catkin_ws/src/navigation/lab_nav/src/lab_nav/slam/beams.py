"""Which LaserScan beams gmapping uses, and where they end, in the laser frame.

gmapping's rules: a range below range_min becomes range_max (and so is dropped below); a beam longer than
maxRange is dropped, as are +inf, -inf and NaN; a beam longer than maxUrange is cut to maxUrange and only marks
the cells it passes as free; the rest end on an obstacle.
"""

from dataclasses import dataclass

import numpy as np


@dataclass(frozen=True)
class Beams:
    """Used beams: end points (N x 2, m, laser frame) and which of them ended on an obstacle (N,)."""

    ends: np.ndarray
    hit: np.ndarray


def scan_beams(ranges, angle_min, angle_increment, range_min, range_max, max_range, max_urange):
    """Beams of one scan (ranges in m, angles in rad CCW from the laser's +x) under the rules above."""
    ranges = np.asarray(ranges, dtype=float)
    angles = angle_min + angle_increment * np.arange(len(ranges))
    with np.errstate(invalid="ignore"):
        ranges = np.where(ranges < range_min, range_max, ranges)
        used = np.isfinite(ranges) & (ranges <= max_range)
    ranges, angles = ranges[used], angles[used]
    hit = ranges <= max_urange
    ranges = np.minimum(ranges, max_urange)
    ends = np.column_stack((ranges * np.cos(angles), ranges * np.sin(angles)))
    return Beams(ends, hit)
