"""nav_bench's goals driven offline: navfn and DWA in a closed loop with exact kinematics and no ROS
(tests/integration/navigation/closed_loop), one line per goal, so a path's excess can be told from load and amcl.

    source scripts/env.sh && python3 tests/bench/nav_offline_bench.py [goals [sim_time]]

The goals are nav_bench's (turtlebot3_world, seed 30), the first from where nav_bench's amcl drive leaves the robot
(START), each next from the previous goal's pose. Per goal: the path over the shortest grid path and over
navfn's cheapest one (which keeps away from obstacles where that is cheap), the share of control cycles that
reversed, the cycles without a valid command (the robot stopped there), the closest the footprint came to a wall.
`sim_time` (s) replaces DWA's 2.0 (turtlebot3 waffle's) to show what the horizon does.
`run()` returns rows [(name, value, unit, target, comparison)] as the other benches do; a few minutes of one core.
"""
import statistics
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from integration.navigation import closed_loop, world_map  # noqa: E402
from integration.navigation.stack import turtlebot3_world_cells  # noqa: E402

from lab_nav.planning.local_planner import DwaParams  # noqa: E402
from roslab import nav_goals  # noqa: E402
from tb3_sim.core.world_file import load_world, shipped_world_path  # noqa: E402

GOALS, SEED = 40, 30
START = (0.0, -0.5, 0.0)   # the spawn point (-2, -0.5) after nav_bench's 2 m amcl drive along x
PATH_RATIO = 1.2


def run(goals=GOALS, sim_time=DwaParams().sim_time):
    cells = turtlebot3_world_cells()
    shapes = load_world(shipped_world_path("turtlebot3_world")).static_shapes
    costs = nav_goals.global_costs(world_map.GEOMETRY, cells)
    goal_list = nav_goals.random_goals(cells, costs, world_map.GEOMETRY, START[:2], goals, SEED)
    params = DwaParams(sim_time=sim_time)
    print(f"  goal  (x, y, yaw)              path/shortest  /cheapest  reversing  stopped  closest  ({goals} goals, "
          f"sim_time {sim_time} s)", flush=True)
    start, driven, reached, closest = START, [], 0, []
    wall = time.monotonic()
    for k, goal in enumerate(goal_list, 1):
        run = closed_loop.drive(cells, shapes, costs, start, goal[:3], params)
        driven.append(run.path_m)
        reached += run.reached
        closest.append(run.closest_m)
        ratio = run.path_m / goal[3]
        mark = "!" if ratio > PATH_RATIO else " "
        print(f"  {k:4d}  ({goal[0]:5.2f}, {goal[1]:5.2f}, {goal[2]:5.2f})  {ratio:13.2f}{mark}"
              f" {run.path_m / goal[4]:9.2f}  {run.reversing / run.cycles:8.0%}  {run.stopped:7d}  {run.closest_m:6.3f}"
              f"{'' if run.reached else '  not reached'}", flush=True)
        start = goal[:3]
    ratios = [path / goal[3] for path, goal in zip(driven, goal_list)]
    over = [k for k, r in enumerate(ratios, 1) if r > PATH_RATIO]
    print(f"  {reached}/{goals} reached, path/shortest median {statistics.median(ratios):.2f}, worst {max(ratios):.2f},"
          f" over {PATH_RATIO}: {over or 'none'} ({time.monotonic() - wall:.0f} s)", flush=True)
    return [
        (f"offline navfn + DWA: goals reached (nav_bench's {goals}, sim_time {sim_time} s)", reached / goals, "",
         0.95, ">="),
        ("offline navfn + DWA: path / shortest grid path, median", statistics.median(ratios), "", PATH_RATIO, "<="),
        ("offline navfn + DWA: path / shortest grid path, worst", max(ratios), "", PATH_RATIO, "<="),
        ("offline navfn + DWA: path / shortest grid path, all goals together",
         sum(driven) / sum(goal[3] for goal in goal_list), "", PATH_RATIO, "<="),
        ("offline navfn + DWA: path / navfn's cheapest path, worst",
         max(path / goal[4] for path, goal in zip(driven, goal_list)), "", PATH_RATIO, "<="),
        ("offline navfn + DWA: closest approach of the footprint to a wall", min(closest), "m", 0.02, ">="),
    ]


if __name__ == "__main__":
    args = sys.argv[1:3]
    for row in run(*([int(args[0])] if args else []), *([float(args[1])] if len(args) > 1 else [])):
        print(row)
