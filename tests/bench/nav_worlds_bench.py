"""Navigation in turtlebot3_house and the course's nav_world for scripts/bench (sim-time figures from a real run;
not a test, never asserted).

    source scripts/env.sh && python3 tests/bench/nav_worlds_bench.py [goals [real_time_factor [world ...]]]

Per world, one session (tests/integration/navigation/stack.py with the world's launch file: the world at FACTOR,
headless, map_server on a map drawn from the world file, amcl from the spawn point, move_base): GOALS seeded random
reachable goals (roslab.nav_goals, seed 30) through the move_base action. Measures the share reached ("Goal
reached.", target 0.95), the share reached where the simulator has the robot within TRUE_XY_M of the goal (amcl's
pose is what move_base judges: a lost amcl "reaches" goals far from them), the path driven over the shortest grid
path (median; target 1.2) and the closest the LiDAR saw anything to the body (target 0.02 m). turtlebot3_world's 40
goals are nav_bench's.
`run()` returns the rows [(name, value, unit, target, comparison)] for scripts/bench's table.
"""
import os
import statistics
import sys
import tempfile
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from integration.navigation import world_map  # noqa: E402
from integration.navigation.stack import start_navigation  # noqa: E402

from roslab import RosMaster, nav_goals  # noqa: E402
from roslab.mapping_routes import ROUTES  # noqa: E402

FACTOR = 5
TRUE_XY_M = 0.25   # test_goal_reaching's bound on the true pose at a reached goal
GOALS, SEED = 6, 30
TOPICS = (("/move_base/result", "move_base_msgs/MoveBaseActionResult"), ("/odom", "nav_msgs/Odometry"),
          ("/scan", "sensor_msgs/LaserScan"), ("/move_base/feedback", "move_base_msgs/MoveBaseActionFeedback"))
WORLDS = ("turtlebot3_house", "nav_world")


def within_walls(cells):
    """`cells` with the free cells outside the occupied cells' bounding box made unknown: turtlebot3_house's doors
    open onto the whole map, and its goals belong in the house and its garden."""
    rows, cols = (np.nonzero(np.asarray(cells) == 100))
    outside = np.ones(cells.shape, bool)
    outside[rows.min():rows.max() + 1, cols.min():cols.max() + 1] = False
    return np.where(outside & (cells == 0), np.int8(-1), cells)


def world_runs(world_name, count, factor):
    """[(goal, run)] of `count` seeded goals in one session of `world_name` (a roslab.mapping_routes world)."""
    route = ROUTES[world_name]
    spawn, robot = route.spawn[:2], route.robot_name("waffle")
    cells = within_walls(world_map.world_cells(world_name, spawn, world_path=route.world_path()))
    costs = nav_goals.global_costs(world_map.GEOMETRY, cells)
    goals = nav_goals.random_goals(cells, costs, world_map.GEOMETRY, spawn, count, SEED)
    master = RosMaster(Path(tempfile.mkdtemp(prefix=f"nav_{world_name}_")))
    os.environ["ROS_MASTER_URI"] = master.uri   # this process calls /gazebo/get_model_state itself
    runs = []
    try:
        probe = start_navigation(master, master.workdir, cells, factor, TOPICS, route.launch, spawn)
        for k, goal in enumerate(goals, 1):
            run = nav_goals.drive_to(probe, goal)
            x, y, _ = nav_goals.true_pose(robot)
            run["true_error"] = float(np.hypot(x - goal[0], y - goal[1]))
            runs.append((goal, run))
            print(f"    {world_name} goal {k}/{count} ({goal[0]:.2f}, {goal[1]:.2f}): {run['text'] or run['status']} "
                  f"in {run['waited']:.1f} s, truth ({x:.2f}, {y:.2f}), path {run['driven']:.2f} m / shortest "
                  f"{goal[3]:.2f} m, clearance {run['clearance']:.3f} m", flush=True)
    finally:
        master.shutdown()
    return runs


def run(goals=GOALS, factor=FACTOR, worlds=WORLDS):
    rows = []
    for world_name in worlds:
        runs = world_runs(world_name, goals, factor)
        reached = [(g, r) for g, r in runs if r["text"] == "Goal reached."]
        ratios = [r["driven"] / g[3] for g, r in reached]
        rows += [
            (f"navigation: random goals reached ({world_name}, factor {factor})", len(reached) / len(runs), "", 0.95,
             ">="),
            (f"navigation: random goals reached with the true pose within {TRUE_XY_M} m ({world_name})",
             sum(r["true_error"] <= TRUE_XY_M for _, r in reached) / len(runs), "", 0.95, ">="),
            (f"navigation: path driven / shortest grid path, median ({world_name})",
             statistics.median(ratios) if ratios else float("inf"), "", 1.2, "<="),
            (f"navigation: closest approach of anything to the body ({world_name})",
             min(r["clearance"] for _, r in runs), "m", 0.02, ">="),
        ]
    return rows


if __name__ == "__main__":
    arguments = sys.argv[1:]
    for row in run(*(int(arg) for arg in arguments[:2]), *([tuple(arguments[2:])] if arguments[2:] else [])):
        print(row)
