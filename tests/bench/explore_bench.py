"""Exploration benchmark for scripts/bench (sim-time figures from a real run; not a test, never asserted).

    source scripts/env.sh && python3 tests/bench/explore_bench.py [real_time_factor]

One session (tests/integration/navigation/exploration.py): turtlebot3_world at FACTOR, turtlebot3_slam.launch,
move_base.launch and explore.launch, hands-off until explore logs "Exploration stopped." (or LIMIT_SIM_S of sim
time). Measures the share of the world's free space /map marks free when exploration stops (target 0.90),
whether it stopped (1 or 0), the sim time it took, the frontiers it blacklisted and the wall time.
`run()` returns the rows [(name, value, unit, target, comparison)] for scripts/bench's table.
"""
import math
import os
import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from integration.navigation import exploration  # noqa: E402

from roslab import RosMaster, nav_goals, wait_until  # noqa: E402

FACTOR = 10
LIMIT_SIM_S = 900.0
POLL_S = 5.0
CONTACT_MARGIN_M = 0.02


def explore(factor):
    """{coverage, stopped, sim_s, blacklisted, clearance, wall_s} of one hands-off exploration."""
    free_xy = exploration.world_free_cells()
    master = RosMaster(Path(tempfile.mkdtemp(prefix="explore_bench_")))
    os.environ["ROS_MASTER_URI"] = master.uri   # this process asks /dynamic_map itself
    clearance = math.inf
    try:
        wall_start = time.monotonic()
        explorer, probe = exploration.start_exploration(master, factor, (("/scan", "sensor_msgs/LaserScan"),))
        sim_start = probe.now()

        def finished():
            nonlocal clearance
            clearance = min(clearance, nav_goals.closest_clearance_m([e["msg"] for e in probe.take("/scan")]))
            grid = exploration.current_map()
            if grid is not None:
                print(f"    {probe.now() - sim_start:5.0f} s sim, {time.monotonic() - wall_start:5.0f} s wall: "
                      f"coverage {exploration.coverage(grid, free_xy):.3f}", flush=True)
            return exploration.STOPPED in explorer.output() or probe.now() - sim_start > LIMIT_SIM_S
        wait_until(finished, LIMIT_SIM_S / factor * 4 + 300, "exploration to stop", interval_s=POLL_S)
        wall_s = time.monotonic() - wall_start
        grid = exploration.current_map()
        output = explorer.output()
    finally:
        master.shutdown()
    result = dict(coverage=exploration.coverage(grid, free_xy), stopped=exploration.STOPPED in output,
                  sim_s=exploration.exploring_sim_s(output) or math.inf,
                  blacklisted=output.count(exploration.BLACKLISTED), clearance=clearance, wall_s=wall_s)
    print("    " + ", ".join(f"{k} {v:.3f}" for k, v in result.items()) + f" (log: {master.workdir})", flush=True)
    return result


def run(factor=FACTOR):
    result = explore(factor)
    return [
        (f"explore_lite: free space of turtlebot3_world mapped, hands-off (factor {factor})", result["coverage"], "",
         0.90, ">="),
        ("explore_lite: 'Exploration stopped.' logged", float(result["stopped"]), "", 1.0, ">="),
        ("explore_lite: sim time from move_base connected to stopped", result["sim_s"], "s", LIMIT_SIM_S, "<="),
        ("explore_lite: frontiers blacklisted", result["blacklisted"], "", 0, ">="),
        ("explore_lite: closest approach of anything to the body", result["clearance"], "m", CONTACT_MARGIN_M,
         ">="),
        (f"explore_lite: wall time from start-up to stopped (factor {factor})", result["wall_s"], "s", 90.0, "<="),
    ]


if __name__ == "__main__":
    for row in run(*(int(arg) for arg in sys.argv[1:2])):
        print(row)
