"""CPU per sim second of each process of the navigation stack (a measurement, never asserted).

    source scripts/env.sh && python3 tests/bench/nav_cpu_bench.py [factor [goals [standing_sim_s]]]

tests/integration/navigation's stack (turtlebot3_world headless at `factor`, map_server, amcl, move_base,
robot_state_publisher) on one master: first the robot standing for `standing_sim_s` (the nodes' cost of merely
receiving /clock, /tf, /odom and /scan), then `goals` seeded reachable goals (roslab.nav_goals, the nav_bench's
seed). For each phase, each node's CPU seconds (all threads, /proc) over the sim seconds that passed, in % of a
core, with the load average, since a loaded machine both slows the simulator and inflates every process's
wake-ups. Factor 10 needs the column's total under 20 % (2 cores, shared).
"""
import os
import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from integration.navigation import world_map  # noqa: E402
from integration.navigation.stack import start_navigation, turtlebot3_world_cells  # noqa: E402
from nav_bench import SEED, TOPICS  # noqa: E402

from roslab import RosMaster, nav_goals  # noqa: E402
from roslab.graph import node_pid  # noqa: E402
from roslab.processes import cpu_seconds  # noqa: E402

NODES = ("/gazebo", "/robot_state_publisher", "/map_server", "/amcl", "/move_base")


def measure(master, probe, phase):
    """{node: CPU % per sim second} over phase(), with the sim and wall seconds it took and the load."""
    pids = {name: node_pid(master.uri, name) for name in NODES}
    cpu_start, sim_start, wall_start = {n: cpu_seconds(p) for n, p in pids.items()}, probe.now(), time.monotonic()
    phase()
    sim_s, wall_s = probe.now() - sim_start, time.monotonic() - wall_start
    cpu = {n: 100.0 * (cpu_seconds(p) - cpu_start[n]) / sim_s for n, p in pids.items()}
    return cpu, sim_s, wall_s, os.getloadavg()[0]


def main(factor=5, goals=3, standing_sim_s=30):
    cells = turtlebot3_world_cells()
    master = RosMaster(Path(tempfile.mkdtemp(prefix="nav_cpu_bench_")))
    os.environ["ROS_MASTER_URI"] = master.uri
    try:
        probe = start_navigation(master, master.workdir, cells, factor, TOPICS)
        probe.sleep_sim(5.0)   # amcl's first update, the costmaps' first full grids
        costs = nav_goals.global_costs(world_map.GEOMETRY, cells)
        goal_list = nav_goals.random_goals(cells, costs, world_map.GEOMETRY, nav_goals.true_pose()[:2], goals, SEED)
        results = {"standing": measure(master, probe, lambda: probe.sleep_sim(standing_sim_s, 120.0))}
        runs = []
        results[f"{goals} goals"] = measure(
            master, probe, lambda: runs.extend(nav_goals.drive_to(probe, g) for g in goal_list))
    finally:
        master.shutdown()
    print(f"factor {factor}; goals: " + ", ".join(f"{r['text'] or r['status']} in {r['waited']:.1f} s" for r in runs))
    print("| process | " + " | ".join(results) + " |")
    print("| --- |" + " --- |" * len(results))
    for node in NODES:
        print(f"| {node} | " + " | ".join(f"{r[0][node]:.1f} %" for r in results.values()) + " |")
    print("| total | " + " | ".join(f"{sum(r[0].values()):.1f} %" for r in results.values()) + " |")
    print("| sim s / wall s (load) | " + " | ".join(f"{r[1]:.0f} / {r[2]:.0f} ({r[3]:.1f})" for r in results.values())
          + " |")


if __name__ == "__main__":
    main(*(int(arg) for arg in sys.argv[1:4]))
