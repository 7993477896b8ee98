"""The SLAM loop as gmapping runs it: which scans are processed, when a map is due, and the map->odom correction.

Each scan comes with the odometry pose of the base at the scan's stamp and the laser's pose on the base. gmapping's
rules decide whether it is processed: always the first; after that when the odometry travelled linearUpdate, turned
angularUpdate, or (temporalUpdate >= 0) more than temporalUpdate of scan time passed since the last processed
scan; only every throttle_scans-th scan is looked at. A processed scan is matched against the map around the
odometry's prediction (odometry composed with the current correction); a match scoring below minimumScore is
rejected and the prediction is used, as gmapping does ("Scan Matching Failed, using odometry"). The scan then goes
into the map at that pose, and the correction becomes map pose (-) odometry pose. A map is due after a processed
scan when it is the first, or when the scan is more than map_update_interval after the last map.

The clock going backwards (a simulator reset) restarts the timing - the next scan is processed and a map sent -
but keeps the map and the correction: the world has not changed and odometry still lives in the same frame.
Odometry that jumps between two scans (a teleport or a reset: farther than a robot can move in that time) leaves
that scan out, and the next: TF interpolates the pose of a scan taken across the jump, so it would go into the
map at a pose the robot never had.
"""

from dataclasses import dataclass
from typing import Optional

import numpy as np

from lab_nav.slam import pose as poses
from lab_nav.slam.beams import scan_beams
from lab_nav.slam.grid import SlamGrid, initial_geometry
from lab_nav.slam.matcher import Match, ScanMatcher

# Odometry moving farther than this between two scans (at least JUMP_M / JUMP_RAD, at most as far as in
# JUMP_WINDOW_S: a node that falls behind sees scans far apart) is a jump, not motion.
JUMP_SPEED_MPS = 1.0
JUMP_TURN_RADPS = 4.0
JUMP_M = 0.5
JUMP_RAD = 1.0
JUMP_WINDOW_S = 1.5


@dataclass(frozen=True)
class LaserScanData:
    """A LaserScan's fields the SLAM reads (ranges in m, angles in rad)."""

    stamp: float
    ranges: np.ndarray
    angle_min: float
    angle_increment: float
    range_min: float
    range_max: float


@dataclass(frozen=True)
class ScanOutcome:
    """What one scan did: processed (and its match, None for the first scan), a map due, the clock jumped back."""

    processed: bool = False
    map_due: bool = False
    match: Optional[Match] = None
    matched: bool = False
    clock_jumped_back: bool = False
    odometry_jumped: bool = False


class Slam:
    """One SLAM run with `params` (a SlamParams)."""

    def __init__(self, params):
        self.params = params
        self.grid = SlamGrid(initial_geometry(params.xmin, params.ymin, params.xmax, params.ymax, params.delta))
        self.matcher = ScanMatcher(params.sigma, params.iterations)
        self.correction = (0.0, 0.0, 0.0)
        self.processed_scans = 0
        self.entropy = 0.0
        self._scans_seen = 0
        self._last_stamp = None
        self._last_scan_odom = None
        self._settling = False
        self._last_odom = None
        self._travel = self._rotation = 0.0
        self._last_processed_stamp = None
        self._last_map_stamp = None

    def map_pose(self, odom_pose):
        """The base's pose in the map frame for its odometry pose."""
        return poses.compose(self.correction, odom_pose)

    def add_scan(self, scan, odom_pose, laser_pose):
        """Take one scan (a LaserScanData) seen with the base at `odom_pose` (odom frame) and the laser at
        `laser_pose` on the base (x, y, yaw; a laser mounted upside down has its angles mirrored by the caller)."""
        jumped = self._last_stamp is not None and scan.stamp < self._last_stamp
        if jumped:
            self._restart_timing()
        odometry_jumped = self._odometry_jumped(scan.stamp, odom_pose, jumped)
        self._last_stamp, self._last_scan_odom = scan.stamp, odom_pose
        if odometry_jumped or self._settling:
            self._settling = odometry_jumped
            self._last_odom = odom_pose
            return ScanOutcome(clock_jumped_back=jumped, odometry_jumped=odometry_jumped)
        self._scans_seen += 1
        if (self._scans_seen - 1) % self.params.throttle_scans:
            return ScanOutcome(clock_jumped_back=jumped)
        self._accumulate(odom_pose)
        if not self._due(scan.stamp):
            return ScanOutcome(clock_jumped_back=jumped)
        match, matched = self._process(scan, odom_pose, laser_pose)
        map_due = self._last_map_stamp is None or scan.stamp - self._last_map_stamp > self.params.map_update_interval
        if map_due:
            self._last_map_stamp = scan.stamp
        return ScanOutcome(True, map_due, match, matched, jumped)

    def occupancy(self):
        """The map as gmapping publishes it: int8 [row, col] of -1/0/100, and its MapGeometry."""
        return self.grid.occupancy(self.params.occ_thresh), self.grid.geometry

    def _odometry_jumped(self, stamp, odom_pose, clock_jumped):
        if self._last_scan_odom is None:
            return False
        dx, dy, dtheta = poses.between(self._last_scan_odom, odom_pose)
        elapsed = 0.0 if clock_jumped else min(max(stamp - self._last_stamp, 0.0), JUMP_WINDOW_S)
        return bool(np.hypot(dx, dy) > max(JUMP_M, JUMP_SPEED_MPS * elapsed)
                    or abs(dtheta) > max(JUMP_RAD, JUMP_TURN_RADPS * elapsed))

    def _restart_timing(self):
        self._last_odom = None
        self._travel = self._rotation = 0.0
        self._last_processed_stamp = None
        self._last_map_stamp = None

    def _accumulate(self, odom_pose):
        if self._last_odom is not None:
            dx, dy, dtheta = poses.between(self._last_odom, odom_pose)
            self._travel += float(np.hypot(dx, dy))
            self._rotation += abs(dtheta)
        self._last_odom = odom_pose

    def _due(self, stamp):
        p = self.params
        return (self._last_processed_stamp is None or self._travel >= p.linear_update
                or self._rotation >= p.angular_update
                or (p.temporal_update >= 0.0 and stamp - self._last_processed_stamp > p.temporal_update))

    def _process(self, scan, odom_pose, laser_pose):
        max_range, max_urange = self.params.ranges_for(scan.range_max)
        beams = scan_beams(scan.ranges, scan.angle_min, scan.angle_increment, scan.range_min, scan.range_max,
                           max_range, max_urange)
        base_ends = _transformed(laser_pose, beams.ends)
        predicted = self.map_pose(odom_pose)
        match, matched, pose = None, False, predicted
        if self.processed_scans:
            match = self.matcher.match(self.grid.occupied(), self.grid.geometry, base_ends[beams.hit], predicted)
            matched = match.score >= self.params.minimum_score and match.score > 0.0
            if matched:
                pose = match.pose
                self.entropy = match.entropy
        self.correction = poses.compose(pose, poses.inverse(odom_pose))
        laser = poses.compose(pose, laser_pose)
        self.grid.integrate(laser[:2], _transformed(pose, base_ends), beams.hit)
        self.processed_scans += 1
        self._last_processed_stamp = scan.stamp
        self._travel = self._rotation = 0.0
        return match, matched


def _transformed(pose, points):
    """Points (N x 2) given in the frame at `pose`, in the frame the pose is given in."""
    c, s = np.cos(pose[2]), np.sin(pose[2])
    x, y = points[:, 0], points[:, 1]
    return np.column_stack((pose[0] + c * x - s * y, pose[1] + s * x + c * y))
