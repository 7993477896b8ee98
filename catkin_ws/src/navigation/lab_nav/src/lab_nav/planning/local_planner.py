"""A DWA local planner as dwa_local_planner samples and scores: one (v, w) command per control cycle.

Each cycle it samples vx_samples x vth_samples constant velocities within what the accelerations allow in one
control period (1 / controller_frequency) and within the speed limits, simulates each for sim_time, drops the
trajectories whose footprint touches a lethal cell or whose centre comes within the inscribed radius of one
(costmap >= 253, or off the costmap), and keeps the cheapest by

  path_distance_bias  * (distance of the end point to the global plan, m)
+ path_distance_bias  * (distance of the point forward_point_distance ahead of the end pose, in the direction of
                         travel, to the plan, m; left out within forward_point_distance of the goal)
+ goal_distance_bias  * (distance of the trajectory to the local goal, m)
+ occdist_scale       * (highest cost the footprint meets along the trajectory).

The local goal is the last plan point inside the local costmap. One deliberate difference from the original:
the goal term takes the trajectory's closest approach to the local goal rather than its end point, so near the
goal a trajectory through it is not scored as overshooting; the path term then favours the one that ends there,
which lets the robot settle within xy_goal_tolerance (0.05 m for turtlebot3) instead of dithering around it.
A second one: the forward point of a reversing trajectory lies behind the robot (the original puts it ahead of
the heading whatever the direction), so backing away from the plan's direction does not score as aligned with
it; with turtlebot3's min_vel_x -0.26 a robot facing across its plan otherwise reversed away from the goal while
the replanned path followed it (18 s in turtlebot3_world).
A third: the original also scores goal_distance_bias * the distance from the nose to the local goal (or, when that
is the goal, to a point forward_point_distance beyond it on the line from the robot), its goal_front cost. It is
left out: at tests/bench/nav_offline_bench.py's goals 4 and 36, which start boxed in between pillars facing away
from the plan, the robot with it and the original's nose crept back a cycle at a time (the next cycle every
reversing trajectory hit a pillar, so it stopped, and from a stop one period's acceleration never reaches
min_vel_theta to turn in place) and drove 7.5 and 6.0 x the shortest path, where it now drives 1.33 and 1.44 x;
with it and the reversing nose above, 1.63 and 1.55 x.
Velocities (v, w) with |v| < min_vel_trans and |w| < min_vel_theta are never commanded (dwa's rule).

Within xy_goal_tolerance of the goal it stops (within the acceleration limits) and turns in place toward the
goal yaw (base_local_planner's latched stop-rotate controller); the goal is reached when the yaw is within
yaw_goal_tolerance and the robot is stopped (|v| < trans_stopped_vel, |w| < theta_stopped_vel).

Poses are (x, y, yaw) in m and rad in the local costmap's frame (odom); velocities in m/s and rad/s.
"""
from dataclasses import dataclass

import numpy as np
from scipy.spatial import cKDTree

from ..angles import normalize
from ..costmap.values import INSCRIBED, LETHAL

FOOTPRINT_OUTLINE_STEP_M = 0.1
"""Spacing of the footprint outline points checked against the costmap: cells are 0.05 m, walls in the costmap
are at least a cell thick and inflated, so every 0.1 m finds a lethal cell the outline crosses."""


@dataclass(frozen=True)
class DwaParams:
    """dwa_local_planner_params_waffle.yaml's values as defaults (TB3 waffle / waffle_pi)."""

    max_vel_x: float = 0.26
    min_vel_x: float = -0.26
    max_vel_trans: float = 0.26
    min_vel_trans: float = 0.13
    max_vel_theta: float = 1.82
    min_vel_theta: float = 0.9
    acc_lim_x: float = 2.5
    acc_lim_theta: float = 3.2
    xy_goal_tolerance: float = 0.05
    yaw_goal_tolerance: float = 0.17
    sim_time: float = 2.0
    vx_samples: int = 20
    vth_samples: int = 40
    controller_frequency: float = 10.0
    path_distance_bias: float = 32.0
    goal_distance_bias: float = 20.0
    occdist_scale: float = 0.02
    forward_point_distance: float = 0.325
    trans_stopped_vel: float = 0.1
    theta_stopped_vel: float = 0.1
    sim_steps: int = 12

    @property
    def sim_period(self):
        return 1.0 / self.controller_frequency


@dataclass(frozen=True)
class Command:
    """The cycle's outcome: velocity (v, w); trajectory (K, 3) chosen (empty when none); reached; valid."""

    v: float
    w: float
    trajectory: np.ndarray
    reached: bool = False
    valid: bool = True


def _failed():
    return Command(0.0, 0.0, np.zeros((0, 3)), valid=False)


class DwaPlanner:
    """Holds the plan handed over by move_base; `compute` gives one cycle's command on a costmap."""

    def __init__(self, params, footprint):
        self.params = params
        self._points = np.vstack(([0.0, 0.0], footprint.outline(FOOTPRINT_OUTLINE_STEP_M)))   # centre first
        self._points32 = self._points.astype(np.float32)
        self._plan = np.zeros((0, 2))
        self._goal = None

    def set_plan(self, plan_xy, goal_pose):
        """The global plan (N, 2) and the goal pose (x, y, yaw), in the local costmap's frame."""
        self._plan = np.asarray(plan_xy, dtype=float).reshape(-1, 2)
        self._goal = tuple(goal_pose)

    def at_goal_position(self, pose):
        return self._goal is not None and np.hypot(pose[0] - self._goal[0], pose[1] - self._goal[1]) <= \
            self.params.xy_goal_tolerance

    def compute(self, pose, velocity, costmap):
        """One control cycle from pose (x, y, yaw) and current velocity (v, w) on a LayeredCostmap."""
        if self._goal is None:
            return _failed()
        if self.at_goal_position(pose):
            return self._stop_and_rotate(pose, velocity, costmap)
        return self._best_trajectory(pose, velocity, costmap)

    # --- sampling -----------------------------------------------------------------------------------------
    def samples(self, velocity):
        """(M, 2) array of the (v, w) samples reachable within one control period and allowed by the limits."""
        p, (v0, w0) = self.params, velocity
        dt = p.sim_period
        vs = np.linspace(max(p.min_vel_x, v0 - p.acc_lim_x * dt), min(p.max_vel_x, v0 + p.acc_lim_x * dt),
                         max(p.vx_samples, 1))
        ws = np.linspace(max(-p.max_vel_theta, w0 - p.acc_lim_theta * dt),
                         min(p.max_vel_theta, w0 + p.acc_lim_theta * dt), max(p.vth_samples, 1))
        v, w = (a.ravel() for a in np.meshgrid(vs, ws))
        ok = (np.abs(v) <= p.max_vel_trans + 1e-9) & ((np.abs(v) >= p.min_vel_trans - 1e-9) |
                                                        (np.abs(w) >= p.min_vel_theta - 1e-9))
        return np.column_stack((v[ok], w[ok]))

    def simulate(self, pose, commands):
        """(M, K, 3) poses of each constant (v, w) over sim_time, K = sim_steps (exact arcs)."""
        p = self.params
        t = np.linspace(p.sim_time / p.sim_steps, p.sim_time, p.sim_steps)
        v, w = commands[:, 0:1], commands[:, 1:2]
        x0, y0, th0 = pose
        th = th0 + w * t
        straight = np.abs(w) < 1e-6
        safe_w = np.where(straight, 1.0, w)
        x = np.where(straight, x0 + v * t * np.cos(th0), x0 + v / safe_w * (np.sin(th) - np.sin(th0)))
        y = np.where(straight, y0 + v * t * np.sin(th0), y0 - v / safe_w * (np.cos(th) - np.cos(th0)))
        return np.stack((x, y, th), axis=-1)

    def footprint_costs(self, poses, costmap):
        """(M, K) highest cost under the footprint outline at each pose, and whether the pose collides (its
        centre on an inscribed cell or the outline on a lethal one): one costmap lookup of every point."""
        g = costmap.geometry
        # in cells from the costmap's origin, float32 (1e-5 of a cell): one multiply-add per point and axis on
        # ~10^5 points, half the memory traffic of float64
        scale = 1.0 / g.resolution
        yaw = poses[..., 2, None]
        c, s = (np.cos(yaw) * scale).astype(np.float32), (np.sin(yaw) * scale).astype(np.float32)
        col = ((poses[..., 0, None] - g.origin_x) * scale).astype(np.float32)
        row = ((poses[..., 1, None] - g.origin_y) * scale).astype(np.float32)
        ox, oy = self._points32[:, 0], self._points32[:, 1]
        costs = costmap.cost_at_cells(col + c * ox - s * oy, row + s * ox + c * oy)
        centre, outline = costs[..., 0], costs[..., 1:].max(axis=-1)
        return np.maximum(outline, centre), (centre >= INSCRIBED) | (outline >= LETHAL)

    # --- scoring ------------------------------------------------------------------------------------------
    def _local_plan(self, costmap):
        inside = costmap.geometry.contains(*costmap.geometry.world_to_cell(self._plan[:, 0], self._plan[:, 1]))
        if not inside.any():
            return self._plan[:1] if len(self._plan) else np.array([self._goal[:2]])
        last = np.nonzero(inside)[0].max()
        return self._plan[:last + 1]

    def _best_trajectory(self, pose, velocity, costmap):
        p = self.params
        commands = self.samples(velocity)
        if len(commands) == 0:
            return _failed()
        trajectories = self.simulate(pose, commands)
        occ, collides = self.footprint_costs(trajectories, costmap)
        valid = ~np.any(collides, axis=1)
        if not valid.any():
            return _failed()
        plan = self._local_plan(costmap)
        local_goal = plan[-1]
        to_plan = cKDTree(plan)   # distances to the nearest plan point
        ends = trajectories[:, -1, :]
        path_cost = to_plan.query(ends[:, :2])[0]
        goal_cost = np.min(np.linalg.norm(trajectories[..., :2] - local_goal, axis=-1), axis=1)
        total = p.path_distance_bias * path_cost + p.goal_distance_bias * goal_cost + \
            p.occdist_scale * occ.max(axis=1)
        if np.hypot(pose[0] - self._goal[0], pose[1] - self._goal[1]) > p.forward_point_distance:
            ahead = p.forward_point_distance * np.where(commands[:, 0] < 0.0, -1.0, 1.0)[:, None]
            forward = ends[:, :2] + ahead * np.column_stack((np.cos(ends[:, 2]), np.sin(ends[:, 2])))
            total = total + p.path_distance_bias * to_plan.query(forward)[0]
        total[~valid] = np.inf
        best = int(np.argmin(total))
        return Command(float(commands[best, 0]), float(commands[best, 1]), trajectories[best])

    # --- at the goal --------------------------------------------------------------------------------------
    def rotate_speed(self, error, w0):
        """|w| (rad/s) to turn toward a yaw `error` (rad) away from an angular speed w0, as base_local_planner's
        LatchedStopRotateController: |error| within the limits, within one period's acceleration of |w0|, no
        faster than stops at the goal yaw (sqrt(2 acc_lim_theta |error|)), and finally within [min_vel_theta,
        max_vel_theta] again, so from a standstill it turns at min_vel_theta at once (0.9 rad/s for the
        Waffle: the acceleration window alone, 0.32 rad/s, is below it)."""
        p = self.params
        limits = (p.min_vel_theta, p.max_vel_theta)
        reach = p.acc_lim_theta * p.sim_period
        speed = np.clip(np.clip(abs(error), *limits), abs(w0) - reach, abs(w0) + reach)
        return float(np.clip(min(speed, np.sqrt(2 * p.acc_lim_theta * abs(error))), *limits))

    def _stop_and_rotate(self, pose, velocity, costmap):
        p, (v0, w0) = self.params, velocity
        dt = p.sim_period
        error = normalize(self._goal[2] - pose[2])
        stopped = abs(v0) < p.trans_stopped_vel and abs(w0) < p.theta_stopped_vel
        if abs(error) <= p.yaw_goal_tolerance and stopped:
            return Command(0.0, 0.0, np.array([pose]), reached=True)
        if abs(error) <= p.yaw_goal_tolerance or abs(v0) >= p.trans_stopped_vel:
            v = float(np.sign(v0) * max(0.0, abs(v0) - p.acc_lim_x * dt))
            w = float(np.sign(w0) * max(0.0, abs(w0) - p.acc_lim_theta * dt))
            return Command(v, w, np.array([pose]))
        w = float(np.sign(error) * self.rotate_speed(error, w0))
        turn = self.simulate(pose, np.array([[0.0, w]]))[0]
        if np.any(self.footprint_costs(turn[None], costmap)[1]):
            return _failed()
        return Command(0.0, w, turn)

