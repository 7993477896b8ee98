"""navfn and DWA in a closed loop on nav_world's map, with exact kinematics and no ROS (tests/integration/navigation's
closed_loop): the robot rounds the end of wall_6 (0.03 m thin, where a robot on a wrong amcl pose once touched it)
to the seeded goal nav_worlds_bench sends there, and its footprint keeps 0.02 m from the walls as the world file
draws them (not the costmap's cells)."""
import math

from integration.navigation import closed_loop, world_map

from roslab import nav_goals
from roslab.mapping_routes import ROUTES
from tb3_sim.core.world_file import load_world

FROM_GOAL, TO_GOAL = (1.925, -1.425), (0.275, -0.925)   # nav_worlds_bench's goals 1 and 2 (seed 30)


def test_dwa_rounds_the_end_of_a_thin_wall_keeping_clear_of_it():
    route = ROUTES["nav_world"]
    cells = world_map.world_cells("nav_world", route.spawn[:2], world_path=route.world_path())
    shapes = load_world(route.world_path()).static_shapes
    costs = nav_goals.global_costs(world_map.GEOMETRY, cells)
    goal = (*TO_GOAL, 0.0)
    run = closed_loop.drive(cells, shapes, costs, (*FROM_GOAL, math.pi), goal)
    assert run.reached and math.hypot(run.pose[0] - goal[0], run.pose[1] - goal[1]) <= 0.05, run
    assert run.closest_m >= 0.02, run
