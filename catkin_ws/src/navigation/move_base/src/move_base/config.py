"""move_base's private parameters, with the originals' defaults (turtlebot3's yaml files set their own).

Names as the original reads them: move_base's own under ~, each costmap's under ~global_costmap/ and
~local_costmap/ (with the pre-Hydro keys turtlebot3 uses: footprint, inflation_radius, cost_scaling_factor,
obstacle_range, raytrace_range, observation_sources), the planners' under ~NavfnROS/ and ~DWAPlannerROS/.
"""
import math
from dataclasses import dataclass, fields

import rospy
import yaml
from nav_ros.params import ParamError, read

from lab_nav.costmap.footprint import Footprint, FootprintError
from lab_nav.costmap.layered import CostmapParams
from lab_nav.planning.local_planner import DwaParams
from lab_nav.planning.move_base_logic import MoveBaseParams

DWA_DEFAULTS = dict(max_vel_x=0.55, min_vel_x=0.0, max_vel_trans=0.55, min_vel_trans=0.1, max_vel_theta=1.0,
                    min_vel_theta=0.4, acc_lim_x=2.5, acc_lim_theta=3.2, xy_goal_tolerance=0.1,
                    yaw_goal_tolerance=0.1, sim_time=1.7, vx_samples=3, vth_samples=20,
                    path_distance_bias=0.6, goal_distance_bias=0.8, occdist_scale=0.01,
                    forward_point_distance=0.325, trans_stopped_vel=0.1, theta_stopped_vel=0.1)
MOVE_BASE_DEFAULTS = dict(planner_frequency=0.0, controller_frequency=20.0, planner_patience=5.0,
                          controller_patience=15.0, max_planning_retries=-1, oscillation_timeout=0.0,
                          oscillation_distance=0.5, recovery_behavior_enabled=True, clearing_rotation_allowed=True,
                          conservative_reset_dist=3.0)
DEFAULT_FOOTPRINT = ((-0.325, -0.325), (-0.325, 0.325), (0.325, 0.325), (0.46, 0.0), (0.325, -0.325))


@dataclass(frozen=True)
class Source:
    """One observation source of the obstacle layer (LaserScan only)."""

    name: str
    topic: str
    marking: bool
    clearing: bool


@dataclass(frozen=True)
class CostmapConfig:
    name: str
    params: CostmapParams
    global_frame: str
    robot_base_frame: str
    update_frequency: float
    publish_frequency: float
    transform_tolerance: float
    static_map: bool
    rolling_window: bool
    width: float
    height: float
    resolution: float
    sources: tuple


def _footprint(name):
    key = f"{name}/footprint"
    value = rospy.get_param("~" + key, None)
    if value is None:
        radius = rospy.get_param(f"~{name}/robot_radius", None)
        if radius is not None:
            angles = [2 * math.pi * i / 16 for i in range(16)]
            value = [[float(radius) * math.cos(a), float(radius) * math.sin(a)] for a in angles]
        else:
            value = DEFAULT_FOOTPRINT
    if isinstance(value, str):   # costmap_2d also accepts the footprint as a string "[[x, y], ...]"
        value = yaml.safe_load(value)
    try:
        return Footprint.padded(value, read(f"{name}/footprint_padding", 0.01))
    except (FootprintError, TypeError, ValueError) as error:
        raise ParamError(f"parameter {rospy.resolve_name('~' + key)}: {error}") from None


def _sources(name):
    listed = read(f"{name}/observation_sources", "", str).split()
    out = []
    for source in listed:
        prefix = f"{name}/{source}/"
        kind = read(prefix + "data_type", "PointCloud", str)
        if kind != "LaserScan":
            rospy.logwarn("%s: observation source %s has data_type %s; only LaserScan is supported here, so it is "
                          "left out", name, source, kind)
            continue
        out.append(Source(source, read(prefix + "topic", source, str), read(prefix + "marking", True, bool),
                          read(prefix + "clearing", False, bool)))
    return tuple(out)


def read_costmap(name, default_static):
    params = CostmapParams(_footprint(name), inflation_radius=read(f"{name}/inflation_radius", 0.55),
                           cost_scaling_factor=read(f"{name}/cost_scaling_factor", 10.0),
                           obstacle_range=read(f"{name}/obstacle_range", 2.5),
                           raytrace_range=read(f"{name}/raytrace_range", 3.0))
    return CostmapConfig(
        name=name, params=params, global_frame=read(f"{name}/global_frame", "map", str).lstrip("/"),
        robot_base_frame=read(f"{name}/robot_base_frame", "base_link", str).lstrip("/"),
        update_frequency=read(f"{name}/update_frequency", 5.0),
        publish_frequency=read(f"{name}/publish_frequency", 0.0),
        transform_tolerance=read(f"{name}/transform_tolerance", 0.3),
        static_map=read(f"{name}/static_map", default_static, bool),
        rolling_window=read(f"{name}/rolling_window", False, bool),
        width=read(f"{name}/width", 10.0), height=read(f"{name}/height", 10.0),
        resolution=read(f"{name}/resolution", 0.05), sources=_sources(name))


def _read_fields(cls, prefix, defaults, **fixed):
    names = {f.name for f in fields(cls)}
    values = {key: read(prefix + key, default, type(default)) for key, default in defaults.items() if key in names}
    return cls(**values, **fixed)


def read_move_base():
    return _read_fields(MoveBaseParams, "", MOVE_BASE_DEFAULTS)


def read_dwa(controller_frequency):
    params = _read_fields(DwaParams, "DWAPlannerROS/", DWA_DEFAULTS, controller_frequency=controller_frequency)
    for key in ("max_vel_x", "max_vel_trans", "max_vel_theta", "acc_lim_x", "acc_lim_theta", "sim_time"):
        if getattr(params, key) <= 0:
            raise ParamError(f"parameter {rospy.resolve_name('~DWAPlannerROS/' + key)} must be > 0")
    return params
