"""amcl's private parameters with the original's defaults (turtlebot3's amcl.launch sets its own values).

The filter's parameters become lab_nav's AmclParams; the node's own (frames, transform_tolerance, initial
pose and covariance, map source, save_pose_rate) stay in AmclNodeConfig. laser_model_type other than
likelihood_field, odom_model_type other than diff/diff-corrected (omni, omni-corrected) and non-zero
recovery_alpha_slow/_fast are not implemented: the node warns and uses what it has (the diff model).
`~seed` (int, default unset = from the OS) seeds the filter so that two runs with the same inputs give the same
particles.
"""
import math
from dataclasses import dataclass

from nav_ros.params import read

from lab_nav.localization.likelihood_field import LaserParams
from lab_nav.localization.motion_model import SPREADS, OdometryNoise
from lab_nav.localization.particle_filter import AmclParams

SUPPORTED_LASER_MODELS = ("likelihood_field",)


@dataclass(frozen=True)
class AmclNodeConfig:
    filter: AmclParams
    seed: object
    global_frame_id: str
    odom_frame_id: str
    base_frame_id: str
    transform_tolerance: float
    tf_broadcast: bool
    use_map_topic: bool
    first_map_only: bool
    save_pose_rate: float
    initial_pose: tuple
    initial_cov: tuple


def read_config(warn):
    """The node's configuration from its private parameters; `warn(text)` reports unsupported choices."""
    laser_model = read("laser_model_type", "likelihood_field", str)
    if laser_model not in SUPPORTED_LASER_MODELS:
        warn(f"laser_model_type {laser_model!r} is not implemented here: using likelihood_field")
    odom_model = read("odom_model_type", "diff", str)
    if odom_model not in SPREADS:
        warn(f"odom_model_type {odom_model!r} is not implemented here: using diff")
        odom_model = "diff"
    if read("recovery_alpha_slow", 0.001) > 0 or read("recovery_alpha_fast", 0.1) > 0:
        warn("recovery_alpha_slow/fast (random particles on a weak match) are not implemented here: no recovery")
    laser = LaserParams(max_beams=read("laser_max_beams", 30, int), max_range=read("laser_max_range", -1.0),
                        min_range=read("laser_min_range", -1.0), z_hit=read("laser_z_hit", 0.95),
                        z_rand=read("laser_z_rand", 0.05), sigma_hit=read("laser_sigma_hit", 0.2),
                        likelihood_max_dist=read("laser_likelihood_max_dist", 2.0))
    noise = OdometryNoise(*(read(f"odom_alpha{i}", 0.2) for i in range(1, 5)))
    params = AmclParams(min_particles=read("min_particles", 100, int), max_particles=read("max_particles", 5000, int),
                        kld_err=read("kld_err", 0.01), kld_z=read("kld_z", 0.99),
                        update_min_d=read("update_min_d", 0.2), update_min_a=read("update_min_a", math.pi / 6.0),
                        resample_interval=read("resample_interval", 2, int), odom_model=odom_model, laser=laser,
                        noise=noise)
    seed = read("seed", None, int)
    return AmclNodeConfig(
        filter=params, seed=seed,
        global_frame_id=read("global_frame_id", "map", str), odom_frame_id=read("odom_frame_id", "odom", str),
        base_frame_id=read("base_frame_id", "base_link", str),
        transform_tolerance=read("transform_tolerance", 0.1), tf_broadcast=read("tf_broadcast", True, bool),
        use_map_topic=read("use_map_topic", False, bool), first_map_only=read("first_map_only", False, bool),
        save_pose_rate=read("save_pose_rate", 0.5),
        initial_pose=(read("initial_pose_x", 0.0), read("initial_pose_y", 0.0), read("initial_pose_a", 0.0)),
        initial_cov=(read("initial_cov_xx", 0.25), read("initial_cov_yy", 0.25),
                     read("initial_cov_aa", (math.pi / 12.0) ** 2)))
