"""2D SLAM from /scan and odometry, as gmapping does it from the outside: log-odds/beam-count occupancy grid
mapping (grid), correlative scan-to-map matching (matcher) correcting the odometry, gmapping's processing rules
(mapper) and parameters (params)."""

from lab_nav.slam.errors import SlamError
from lab_nav.slam.mapper import LaserScanData, ScanOutcome, Slam
from lab_nav.slam.params import SlamParams, params_from_dict

__all__ = ["LaserScanData", "ScanOutcome", "Slam", "SlamError", "SlamParams", "params_from_dict"]
