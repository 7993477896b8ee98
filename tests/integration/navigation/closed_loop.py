"""navfn and DWA in a closed loop on a map drawn from a world file, with exact kinematics and no ROS: what move_base
would drive on a perfect localisation and odometry, so a path's shape is the planners' own, not load or amcl.

Each control cycle (0.1 s, controller_frequency) builds move_base's 3 x 3 m local costmap round the robot from the
map's cells (where its scans would mark), hands DWA the plan from its point nearest the robot on, and integrates the
command in 0.01 s steps; navfn replans every second cycle (planner_frequency 5 Hz) on the global costmap. A cycle
without a valid command stops the robot, as move_base's zero Twist does. Used by tests/unit/lab_nav/test_closed_loop.py
and tests/bench/nav_offline_bench.py.
"""
import math
from dataclasses import dataclass

import numpy as np

from lab_nav.costmap.footprint import WAFFLE_FOOTPRINT, Footprint
from lab_nav.costmap.layered import CostmapParams, LayeredCostmap
from lab_nav.maps.geometry import MapGeometry
from lab_nav.planning import global_planner
from lab_nav.planning.local_planner import DwaParams, DwaPlanner

from . import world_map

PLAN_EVERY = 2            # move_base plans at 5 Hz, controls at 10 Hz
STEPS_PER_CYCLE = 10      # kinematics in 0.01 s steps within each 0.1 s control period
MAX_CYCLES = 900          # 90 s of sim time, nav_goals' goal timeout
LOCAL_CELLS = 60          # turtlebot3's local costmap: 3 x 3 m at 0.05 m


@dataclass(frozen=True)
class Drive:
    """One goal driven: reached ("Goal reached."), the final pose (x, y, yaw), the path length (m), the closest the
    unpadded footprint came to a wall (m), the control cycles taken, those that commanded reversing and those that
    found no valid command (the robot stopped)."""

    reached: bool
    pose: tuple
    path_m: float
    closest_m: float
    cycles: int
    reversing: int
    stopped: int


def clearance(shapes, pose):
    """Distance (m) from the unpadded footprint's outline at `pose` to the nearest of the world's static shapes."""
    polygon = Footprint(WAFFLE_FOOTPRINT).placed(*pose)
    t = np.linspace(0.0, 1.0, 30)[:, None]
    points = np.vstack([a + t * (b - a) for a, b in zip(polygon, np.roll(polygon, -1, axis=0))])
    return min(float(world_map._distance(shape, points[:, 0], points[:, 1]).min()) for shape in shapes)


def local_costmap(geometry, cells, footprint, pose):
    """move_base's local costmap round the robot, from the map's cells."""
    col, row = (int(v) - LOCAL_CELLS // 2 for v in geometry.world_to_cell(pose[0], pose[1]))
    window = MapGeometry(geometry.resolution, LOCAL_CELLS, LOCAL_CELLS, geometry.origin_x + col * geometry.resolution,
                         geometry.origin_y + row * geometry.resolution)
    costmap = LayeredCostmap(window, CostmapParams(footprint))
    costmap.set_map(window, cells[row:row + LOCAL_CELLS, col:col + LOCAL_CELLS])
    costmap.update()
    return costmap


def _cell(geometry, xy):
    return tuple(int(v) for v in geometry.world_to_cell(xy[0], xy[1]))


def _plan(navfn, geometry, costs, pose, goal):
    cells = navfn.plan(costs, _cell(geometry, pose), _cell(geometry, goal), geometry.resolution)
    if cells is None:
        return None
    cols, rows = np.array(cells).T
    return np.vstack((np.column_stack(geometry.cell_center(cols, rows)), goal[:2]))


def drive(cells, shapes, costs, start, goal, params=DwaParams(), geometry=world_map.GEOMETRY):
    """Drive from `start` to `goal` (x, y, yaw) on the map `cells` with global costmap `costs` (nav_goals'
    global_costs); `shapes` are the world's static shapes the clearance is measured to."""
    footprint = Footprint.padded(WAFFLE_FOOTPRINT)
    navfn, dwa = global_planner.Navfn(), DwaPlanner(params, footprint)
    pose, velocity = np.array(start, dtype=float), (0.0, 0.0)
    path, closest, reversing, stopped, reached = 0.0, math.inf, 0, 0, False
    dt = params.sim_period / STEPS_PER_CYCLE
    for cycle in range(MAX_CYCLES):
        if cycle % PLAN_EVERY == 0:
            plan = _plan(navfn, geometry, costs, pose, goal)
        if plan is None:
            break
        nearest = int(np.argmin(np.hypot(*(plan - pose[:2]).T)))
        dwa.set_plan(plan[nearest:], goal)
        command = dwa.compute(tuple(pose), velocity, local_costmap(geometry, cells, footprint, pose))
        if command.reached:
            reached = True
            break
        velocity = (command.v, command.w) if command.valid else (0.0, 0.0)
        stopped += not command.valid
        reversing += velocity[0] < 0.0
        for _ in range(STEPS_PER_CYCLE):
            step = (velocity[0] * math.cos(pose[2]) * dt, velocity[0] * math.sin(pose[2]) * dt, velocity[1] * dt)
            pose = pose + step
            path += abs(velocity[0]) * dt
        closest = min(closest, clearance(shapes, pose))
    return Drive(reached, tuple(pose), path, closest, cycle + 1, reversing, stopped)
