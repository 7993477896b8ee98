"""slam_gmapping's private parameters as one validated, typed object (the node passes rospy.get_param("~")).

Names, defaults and meanings are gmapping's (slam_gmapping 1.4.2). The ones that change what this SLAM does:

    base_frame / odom_frame / map_frame   base_link / odom / map   the frames used
    map_update_interval   5.0 s    minimum scan-time gap between two map publications
    maxRange              scan's range_max - 0.01   beams longer than this (and +inf, NaN) are dropped
    maxUrange             maxRange   longer beams are cut to this length and mark free space only
    sigma                 0.05 m   width of the matcher's likelihood field around occupied cells
    iterations            5        Gauss-Newton steps refining the correlative match below a cell
    minimumScore          0        a match scoring below this is rejected and odometry is used
    linearUpdate          1.0 m    process a scan after this much travel ...
    angularUpdate         0.5 rad  ... or this much rotation ...
    temporalUpdate        -1 s     ... or this much scan time since the last processed one (< 0: never)
    xmin ymin xmax ymax   -100 -100 100 100 m   the map's initial extent in the map frame
    delta                 0.05 m   resolution
    occ_thresh            0.25     hit fraction above which a cell is published as 100
    throttle_scans        1        use every Nth scan
    transform_publish_period  0.05 s   map->odom TF period (0: no TF)
    tf_delay              transform_publish_period   how far into the future the TF is stamped

Accepted, checked to be numbers and otherwise ignored (they tune gmapping's particle filter and its
hill-climbing matcher, which this single-hypothesis correlative matcher does not have): particles,
resampleThreshold, srr, srt, str, stt, kernelSize, lstep, astep, lsigma, ogain, lskip, llsamplerange,
llsamplestep, lasamplerange, lasamplestep. Unknown names are ignored, as gmapping ignores them.
"""

import math
from dataclasses import dataclass
from typing import Optional

from lab_nav.slam.errors import SlamError

IGNORED_NUMBERS = ("particles", "resampleThreshold", "srr", "srt", "str", "stt", "kernelSize", "lstep", "astep",
                   "lsigma", "ogain", "lskip", "llsamplerange", "llsamplestep", "lasamplerange", "lasamplestep")


@dataclass(frozen=True)
class SlamParams:
    """Validated settings; maxRange/maxUrange None: from the first scan's range_max, as gmapping does."""

    base_frame: str = "base_link"
    odom_frame: str = "odom"
    map_frame: str = "map"
    map_update_interval: float = 5.0
    max_range: Optional[float] = None
    max_urange: Optional[float] = None
    sigma: float = 0.05
    iterations: int = 5
    minimum_score: float = 0.0
    linear_update: float = 1.0
    angular_update: float = 0.5
    temporal_update: float = -1.0
    xmin: float = -100.0
    ymin: float = -100.0
    xmax: float = 100.0
    ymax: float = 100.0
    delta: float = 0.05
    occ_thresh: float = 0.25
    throttle_scans: int = 1
    transform_publish_period: float = 0.05
    tf_delay: float = 0.05

    def ranges_for(self, scan_range_max):
        """(maxRange, maxUrange) for a laser whose range_max is `scan_range_max`."""
        max_range = self.max_range if self.max_range is not None else scan_range_max - 0.01
        max_urange = self.max_urange if self.max_urange is not None else max_range
        return max_range, min(max_urange, max_range)


def params_from_dict(params):
    """SlamParams from the node's private parameters `params` (a dict). Raises SlamError naming the parameter."""
    read = _Reader(params)
    for key in IGNORED_NUMBERS:
        read.number(key, 0.0)
    period = read.number("transform_publish_period", 0.05, minimum=0.0)
    settings = SlamParams(
        base_frame=read.frame("base_frame", "base_link"),
        odom_frame=read.frame("odom_frame", "odom"),
        map_frame=read.frame("map_frame", "map"),
        map_update_interval=read.number("map_update_interval", 5.0, minimum=0.0),
        max_range=read.optional_positive("maxRange"),
        max_urange=read.optional_positive("maxUrange"),
        sigma=read.number("sigma", 0.05, minimum=0.0, exclusive=True),
        iterations=int(read.number("iterations", 5, minimum=0.0)),
        minimum_score=read.number("minimumScore", 0.0, minimum=0.0),
        linear_update=read.number("linearUpdate", 1.0, minimum=0.0),
        angular_update=read.number("angularUpdate", 0.5, minimum=0.0),
        temporal_update=read.number("temporalUpdate", -1.0),
        xmin=read.number("xmin", -100.0),
        ymin=read.number("ymin", -100.0),
        xmax=read.number("xmax", 100.0),
        ymax=read.number("ymax", 100.0),
        delta=read.number("delta", 0.05, minimum=0.0, exclusive=True),
        occ_thresh=read.number("occ_thresh", 0.25, minimum=0.0),
        throttle_scans=int(read.number("throttle_scans", 1, minimum=1.0)),
        transform_publish_period=period,
        tf_delay=read.number("tf_delay", period, minimum=0.0),
    )
    if settings.occ_thresh >= 1.0:
        raise SlamError(f"~occ_thresh must be in [0, 1), got {settings.occ_thresh!r}")
    for low, high in (("xmin", "xmax"), ("ymin", "ymax")):
        if getattr(settings, low) >= getattr(settings, high):
            raise SlamError(f"~{low} must be less than ~{high}, got {getattr(settings, low)!r} and "
                            f"{getattr(settings, high)!r}")
    return settings


class _Reader:
    def __init__(self, params):
        self._params = params

    def number(self, key, default, minimum=None, exclusive=False):
        value = self._params.get(key, default)
        if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value):
            raise SlamError(f"~{key} must be a finite number, got {value!r}")
        if minimum is not None and (value <= minimum if exclusive else value < minimum):
            raise SlamError(f"~{key} must be {'>' if exclusive else '>='} {minimum:g}, got {value!r}")
        return float(value)

    def optional_positive(self, key):
        return self.number(key, None, minimum=0.0, exclusive=True) if key in self._params else None

    def frame(self, key, default):
        value = self._params.get(key, default)
        if not isinstance(value, str) or not value.strip("/") or any(c.isspace() for c in value):
            raise SlamError(f"~{key} must be a frame name (no spaces), got {value!r}")
        return value.lstrip("/")
