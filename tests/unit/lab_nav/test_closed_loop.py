"""navfn and DWA in a closed loop on nav_world's map, with exact kinematics and no ROS: the robot rounds the end of
wall_6 (0.03 m thin, where a robot on a wrong amcl pose once touched it) to the seeded goal nav_worlds_bench sends
there, and its footprint keeps 0.02 m from the walls as the world file draws them (not the costmap's cells)."""
import math

import numpy as np
from integration.navigation import world_map

from lab_nav.costmap.footprint import WAFFLE_FOOTPRINT, Footprint
from lab_nav.costmap.layered import CostmapParams, LayeredCostmap
from lab_nav.maps.geometry import MapGeometry
from lab_nav.planning import global_planner
from lab_nav.planning.local_planner import DwaParams, DwaPlanner
from roslab import nav_goals
from roslab.mapping_routes import ROUTES
from tb3_sim.core.world_file import load_world

GEOMETRY = world_map.GEOMETRY
PARAMS = DwaParams()
PLAN_EVERY = 2            # move_base plans at 5 Hz, controls at 10 Hz
STEPS_PER_CYCLE = 10      # kinematics in 0.01 s steps within each 0.1 s control period
MAX_CYCLES = 600          # 60 s of sim time
LOCAL_CELLS = 60          # turtlebot3's local costmap: 3 x 3 m at 0.05 m
FROM_GOAL, TO_GOAL = (1.925, -1.425), (0.275, -0.925)   # nav_worlds_bench's goals 1 and 2 (seed 30)


def _walls():
    route = ROUTES["nav_world"]
    cells = world_map.world_cells("nav_world", route.spawn[:2], world_path=route.world_path())
    return cells, load_world(route.world_path()).static_shapes


def _clearance(shapes, pose):
    """Distance (m) from the unpadded footprint's outline at `pose` to the nearest wall."""
    polygon = Footprint(WAFFLE_FOOTPRINT).placed(*pose)
    t = np.linspace(0.0, 1.0, 30)[:, None]
    points = np.vstack([a + t * (b - a) for a, b in zip(polygon, np.roll(polygon, -1, axis=0))])
    return min(float(world_map._distance(shape, points[:, 0], points[:, 1]).min()) for shape in shapes)


def _local_costmap(cells, footprint, pose):
    """move_base's 3 x 3 m local costmap round the robot, from the map's cells (where its scans would mark)."""
    col, row = (int(v) - LOCAL_CELLS // 2 for v in GEOMETRY.world_to_cell(pose[0], pose[1]))
    window = MapGeometry(GEOMETRY.resolution, LOCAL_CELLS, LOCAL_CELLS, GEOMETRY.origin_x + col * GEOMETRY.resolution,
                         GEOMETRY.origin_y + row * GEOMETRY.resolution)
    costmap = LayeredCostmap(window, CostmapParams(footprint))
    costmap.set_map(window, cells[row:row + LOCAL_CELLS, col:col + LOCAL_CELLS])
    costmap.update()
    return costmap


def _plan(navfn, costs, pose, goal):
    cells = navfn.plan(costs, tuple(int(v) for v in GEOMETRY.world_to_cell(pose[0], pose[1])),
                       tuple(int(v) for v in GEOMETRY.world_to_cell(goal[0], goal[1])), GEOMETRY.resolution)
    assert cells is not None
    cols, rows = np.array(cells).T
    return np.vstack((np.column_stack(GEOMETRY.cell_center(cols, rows)), goal[:2]))


def test_dwa_rounds_the_end_of_a_thin_wall_keeping_clear_of_it():
    cells, shapes = _walls()
    footprint = Footprint.padded(WAFFLE_FOOTPRINT)
    costs = nav_goals.global_costs(GEOMETRY, cells)
    navfn, dwa = global_planner.Navfn(), DwaPlanner(PARAMS, footprint)
    goal = (*TO_GOAL, 0.0)
    pose, velocity, closest = np.array([*FROM_GOAL, math.pi]), (0.0, 0.0), math.inf
    for cycle in range(MAX_CYCLES):
        if cycle % PLAN_EVERY == 0:
            plan = _plan(navfn, costs, pose, goal)
        nearest = int(np.argmin(np.hypot(*(plan - pose[:2]).T)))
        dwa.set_plan(plan[nearest:], goal)
        command = dwa.compute(tuple(pose), velocity, _local_costmap(cells, footprint, pose))
        if command.reached:
            break
        velocity = (command.v, command.w) if command.valid else (0.0, 0.0)
        for _ in range(STEPS_PER_CYCLE):
            dt = PARAMS.sim_period / STEPS_PER_CYCLE
            pose = pose + (velocity[0] * math.cos(pose[2]) * dt, velocity[0] * math.sin(pose[2]) * dt,
                           velocity[1] * dt)
        closest = min(closest, _clearance(shapes, pose))
    assert command.reached and math.hypot(pose[0] - goal[0], pose[1] - goal[1]) <= PARAMS.xy_goal_tolerance
    assert closest >= 0.02
