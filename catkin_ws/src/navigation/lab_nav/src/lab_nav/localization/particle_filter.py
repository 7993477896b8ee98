"""amcl's adaptive particle filter: initial Gaussian or uniform global spread, odometry motion, likelihood-field
weighting, low-variance resampling with a KLD-limited sample count, and the pose estimate with its covariance.

The filter updates only after the odometry has moved update_min_d in x or y or turned update_min_a since the last
update (or once on request, or on the first scan), as amcl does; poses between updates come from odometry alone.
The particle count after resampling is the KLD bound for the histogram bins (KLD_BIN_XY_M, KLD_BIN_YAW_RAD) the
samples fill, between min_particles and max_particles, with amcl's quirk of using kld_z (0.99) itself as the
normal quantile. Recovery by random particles (recovery_alpha_slow/fast) is off in turtlebot3's config and not
implemented. All randomness comes from one numpy Generator seeded by `seed`, so a run is reproducible.
"""
from dataclasses import dataclass, field

import numpy as np

from ..angles import normalize
from . import likelihood_field, motion_model
from .likelihood_field import LaserParams, LikelihoodField
from .motion_model import OdometryNoise

KLD_BIN_XY_M = 0.5
KLD_BIN_YAW_RAD = np.radians(10.0)
CLUSTER_RADIUS_M = 1.0


@dataclass(frozen=True)
class AmclParams:
    """turtlebot3's amcl.launch values as defaults (m, rad)."""

    min_particles: int = 500
    max_particles: int = 3000
    kld_err: float = 0.02
    kld_z: float = 0.99
    update_min_d: float = 0.2
    update_min_a: float = 0.2
    resample_interval: int = 1
    odom_model: str = "diff"
    laser: LaserParams = field(default_factory=LaserParams)
    noise: OdometryNoise = field(default_factory=OdometryNoise)


def kld_limit(bins, err, z):
    """How many samples the KLD bound asks for when they fill `bins` histogram bins (amcl's formula)."""
    if bins <= 1:
        return 1
    b = 2.0 / (9.0 * (bins - 1))
    x = 1.0 - b + np.sqrt(b) * z
    return int(np.ceil((bins - 1) / (2.0 * err) * x ** 3))


@dataclass(frozen=True)
class Estimate:
    """The filter's pose (x, y, yaw) and its 3x3 covariance (x, y, yaw; yaw variance circular)."""

    pose: tuple
    covariance: np.ndarray


class ParticleFilter:
    """Particles (N, 3) [x, y, yaw] in the map frame with weights summing to 1."""

    def __init__(self, field_, params=AmclParams(), seed=None):
        self.field = field_
        self.params = params
        self.rng = np.random.default_rng(seed)
        self.particles = np.zeros((0, 3))
        self.weights = np.zeros(0)
        self._last_update_odom = None
        self._force_update = True
        self._updates = 0

    @classmethod
    def for_map(cls, geometry, occupancy, params=AmclParams(), seed=None):
        return cls(LikelihoodField(geometry, occupancy, params.laser.likelihood_max_dist), params, seed)

    # --- initialisation -----------------------------------------------------------------------------------
    def init_gaussian(self, mean, covariance):
        """max_particles samples around mean (x, y, yaw) with the 3x3 covariance; the next scan updates."""
        cov = np.asarray(covariance, dtype=float)
        n = self.params.max_particles
        samples = self.rng.multivariate_normal(np.asarray(mean, dtype=float), cov, size=n, method="cholesky"
                                               if np.all(np.linalg.eigvalsh(cov) > 0) else "eigh")
        samples[:, 2] = normalize(samples[:, 2])
        self._set(samples)

    def init_uniform(self):
        """global_localization: max_particles poses spread over the map's free cells, any yaw."""
        rows, cols = np.nonzero(self.field.free)
        if rows.size == 0:
            raise ValueError("the map has no free cell to spread the particles over")
        n = self.params.max_particles
        pick = self.rng.integers(0, rows.size, n)
        x, y = self.field.geometry.cell_center(cols[pick], rows[pick])
        self._set(np.column_stack((x, y, self.rng.uniform(-np.pi, np.pi, n))))

    def _set(self, particles):
        self.particles = particles
        self.weights = np.full(len(particles), 1.0 / len(particles))
        self._force_update = True

    def request_update(self):
        """request_nomotion_update: update on the next scan even without motion."""
        self._force_update = True

    # --- the update ---------------------------------------------------------------------------------------
    def motion_due(self, odom_pose):
        """True when odometry moved enough since the last update (or an update was asked for)."""
        if self._force_update or self._last_update_odom is None:
            return True
        last = self._last_update_odom
        dx, dy = odom_pose[0] - last[0], odom_pose[1] - last[1]
        da = abs(float(normalize(odom_pose[2] - last[2])))
        d = self.params.update_min_d
        return abs(dx) > d or abs(dy) > d or da > self.params.update_min_a

    def update(self, odom_pose, laser_pose, ranges, angles, range_max):
        """Move the particles by the odometry since the last update, weight them by the scan and resample.

        odom_pose: base in odom at the scan's stamp; laser_pose: the laser in the base frame; ranges and angles
        (rad, in the laser frame) of the whole scan. Returns True when the filter resampled (amcl_pose is due).
        """
        if self._last_update_odom is not None:
            self.particles = motion_model.sample(self.particles, self._last_update_odom, odom_pose,
                                                 self.params.noise, self.rng, self.params.odom_model)
        self._last_update_odom = tuple(odom_pose)
        self._force_update = False
        laser = self.params.laser
        r, a = likelihood_field.select_beams(ranges, angles, laser, range_max)
        if r.size:
            max_range = laser.max_range if laser.max_range > 0 else range_max
            w = self.weights * likelihood_field.weights(self.field, self.particles, laser_pose, r, a, laser,
                                                        max_range)
            self.weights = w / w.sum()
        self._updates += 1
        if self._updates % max(self.params.resample_interval, 1) == 0:
            self.resample()
            return True
        return False

    def resample(self):
        """Low-variance resampling, stopping at the KLD bound (between min_ and max_particles)."""
        p = self.params
        n = p.max_particles
        positions = (self.rng.uniform() + np.arange(n)) / n
        picked = np.searchsorted(np.cumsum(self.weights), positions, side="right")
        picked = np.minimum(picked, len(self.weights) - 1)
        samples = self.particles[self.rng.permutation(picked)]
        keys = np.column_stack((np.floor(samples[:, 0] / KLD_BIN_XY_M), np.floor(samples[:, 1] / KLD_BIN_XY_M),
                                np.floor(samples[:, 2] / KLD_BIN_YAW_RAD))).astype(np.int64)
        _, first = np.unique(keys, axis=0, return_index=True)
        new_bin = np.zeros(n, dtype=int)
        new_bin[first] = 1
        bins = np.cumsum(new_bin)
        limits = np.array([kld_limit(k, p.kld_err, p.kld_z) for k in range(1, bins[-1] + 1)])[bins - 1]
        enough = np.nonzero(np.arange(1, n + 1) >= np.maximum(limits, p.min_particles))[0]
        count = int(enough[0]) + 1 if enough.size else n
        self.particles = samples[:count].copy()
        self.weights = np.full(count, 1.0 / count)

    # --- the estimate -------------------------------------------------------------------------------------
    def estimate(self):
        """Mean and covariance of the heaviest cluster: particles within CLUSTER_RADIUS_M of the heaviest
        KLD bin's weighted centre (amcl reports its heaviest cluster, not the mean of a split cloud)."""
        keys = np.floor(self.particles[:, :2] / KLD_BIN_XY_M).astype(np.int64)
        uniq, inverse = np.unique(keys, axis=0, return_inverse=True)
        heaviest = np.argmax(np.bincount(inverse.ravel(), weights=self.weights))
        members = inverse.ravel() == heaviest
        centre = np.average(self.particles[members, :2], axis=0, weights=self.weights[members])
        cluster = np.linalg.norm(self.particles[:, :2] - centre, axis=1) <= CLUSTER_RADIUS_M
        pts, w = self.particles[cluster], self.weights[cluster] / self.weights[cluster].sum()
        mean_xy = w @ pts[:, :2]
        c, s = w @ np.cos(pts[:, 2]), w @ np.sin(pts[:, 2])
        yaw = float(np.arctan2(s, c))
        cov = np.zeros((3, 3))
        d = pts[:, :2] - mean_xy
        cov[:2, :2] = (w[:, None] * d).T @ d
        cov[2, 2] = -2.0 * np.log(max(np.hypot(c, s), 1e-12))
        return Estimate((float(mean_xy[0]), float(mean_xy[1]), yaw), cov)
