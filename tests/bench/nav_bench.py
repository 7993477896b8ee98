"""Navigation benchmarks for scripts/bench (sim-time figures from a real run; not a test, never asserted).

    source scripts/env.sh && python3 tests/bench/nav_bench.py [goals [real_time_factor]]

One session: turtlebot3_world.launch at real time (headless) and tests/integration/navigation's navigation.launch
(map_server on a map drawn from the world, amcl, move_base with turtlebot3's waffle parameters). Measures:
- amcl: /initialpose 0.3 m and 15 deg off the true pose, the robot driven 2 m straight (0.2 m/s on /cmd_vel),
  then /amcl_pose against /gazebo/get_model_state (targets 0.05 m and 3 deg);
- GOALS (the issue's 40) seeded random reachable goals (roslab.nav_goals, seed 30) through the move_base action,
  the first CPU_GOALS at real time, the rest at FACTOR (set as Gazebo's is, through
  /gazebo/set_physics_properties; the 40 at real time would take half an hour): the share
  reached ("Goal reached.", target 0.95), the path driven over the shortest grid path (median and worst; and
  the worst over the cheapest path by navfn's cost, which keeps away from obstacles; target 1.2 for each),
  the median time to the goal over the shortest path at the speed limit (0.26 m/s; target 2.0, a choice:
  the robot turns toward each goal and slows near it), the closest the LiDAR saw anything to the body;
- CPU of amcl (target 15 % of a core) and move_base (25 %) at real time, measured as CPU seconds per second of
  sim time over the first CPU_GOALS goals: the nodes' work is paced by sim time (scans, 10 Hz control, 5 Hz
  planning), their threads' polling by wall time, so the share per sim second falls with the factor;
- the highest of SWEEP_FACTORS at which SWEEP_GOALS goals are all reached, each factor on a fresh stack, going up
  until one misses (target 10, the issue's factor for a whole exercise).
`run()` returns the rows [(name, value, unit, target, comparison)] for scripts/bench's table.
"""
import math
import os
import statistics
import sys
import tempfile
import time
from pathlib import Path

import rospy
from gazebo_msgs.srv import GetPhysicsProperties, SetPhysicsProperties

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from integration.navigation import world_map  # noqa: E402
from integration.navigation.stack import start_navigation, turtlebot3_world_cells  # noqa: E402

from roslab import RosMaster, nav_goals  # noqa: E402
from roslab.graph import node_pid  # noqa: E402
from roslab.processes import cpu_seconds  # noqa: E402

FACTOR = 5
GOALS, SEED, CPU_GOALS = 40, 30, 3
SWEEP_FACTORS, SWEEP_GOALS = (2, 3, 5, 10), 3
MAX_VEL_M_S = 0.26
AMCL_OFFSET = (0.3, math.radians(15.0))
DRIVE_M_S, DRIVE_SIM_S = 0.2, 10.0
TOPICS = (("/move_base/result", "move_base_msgs/MoveBaseActionResult"), ("/odom", "nav_msgs/Odometry"),
          ("/scan", "sensor_msgs/LaserScan"), ("/move_base/feedback", "move_base_msgs/MoveBaseActionFeedback"),
          ("/amcl_pose", "geometry_msgs/PoseWithCovarianceStamped"))


def set_real_time_factor(factor):
    """Pace the simulator at `factor` as Gazebo is paced: max_update_rate = factor / time_step."""
    now = rospy.ServiceProxy("/gazebo/get_physics_properties", GetPhysicsProperties)()
    reply = rospy.ServiceProxy("/gazebo/set_physics_properties", SetPhysicsProperties)(
        time_step=now.time_step, max_update_rate=factor / now.time_step, gravity=now.gravity,
        ode_config=now.ode_config)
    if not reply.success:
        raise RuntimeError(f"set_physics_properties: {reply.status_message}")


def goal_runs(master, probe, goals, first=1):
    """[run] of each goal in turn (numbered from `first`) and the CPU of amcl and move_base per sim second (%)."""
    pids = {name: node_pid(master.uri, name) for name in ("/amcl", "/move_base")}
    cpu_start, sim_start, wall_start = {n: cpu_seconds(p) for n, p in pids.items()}, probe.now(), time.monotonic()
    runs = []
    for k, goal in enumerate(goals, first):
        run = nav_goals.drive_to(probe, goal)
        runs.append(run)
        print(f"    goal {k} ({goal[0]:.2f}, {goal[1]:.2f}): {run['text'] or run['status']} in "
              f"{run['waited']:.1f} s, path {run['driven']:.2f} m / shortest {goal[3]:.2f} m, clearance "
              f"{run['clearance']:.3f} m", flush=True)
    sim_s, wall_s = probe.now() - sim_start, time.monotonic() - wall_start
    cpu = {n: 100.0 * (cpu_seconds(p) - cpu_start[n]) / sim_s for n, p in pids.items()}
    print(f"    {len(goals)} goals: {sim_s:.0f} s of sim time in {wall_s:.0f} s wall ({sim_s / wall_s:.1f}x); CPU per "
          f"sim second: amcl {cpu['/amcl']:.0f} %, move_base {cpu['/move_base']:.0f} %", flush=True)
    return runs, cpu


def seeded_goals(cells, count):
    costs = nav_goals.global_costs(world_map.GEOMETRY, cells)
    return nav_goals.random_goals(cells, costs, world_map.GEOMETRY, nav_goals.true_pose()[:2], count, SEED)


def _median(values):
    """The median; +inf (a target missed) when no goal was reached."""
    values = list(values)
    return statistics.median(values) if values else math.inf


def _session(factor, work):
    """Start the stack at `factor` on a fresh master, run work(master, probe, cells), shut everything down."""
    cells = turtlebot3_world_cells()
    master = RosMaster(Path(tempfile.mkdtemp(prefix="nav_bench_")))
    os.environ["ROS_MASTER_URI"] = master.uri   # this process calls /gazebo/get_model_state itself
    try:
        return work(master, start_navigation(master, master.workdir, cells, factor, TOPICS), cells)
    finally:
        master.shutdown()


def highest_factor(factors=SWEEP_FACTORS, goals=SWEEP_GOALS):
    """The highest factor (0 when none) from which every one of `goals` goals was reached, trying in order."""
    best = 0
    for factor in factors:
        print(f"  factor {factor}:", flush=True)
        runs = _session(factor, lambda master, probe, cells: goal_runs(master, probe, seeded_goals(cells, goals))[0])
        if not all(r["text"] == "Goal reached." for r in runs):
            break
        best = factor
    return best


def run(goals=GOALS, factor=FACTOR):
    def measure(master, probe, cells):
        amcl = nav_goals.amcl_error_after_drive(probe, *AMCL_OFFSET, DRIVE_M_S, DRIVE_SIM_S)
        goal_list = seeded_goals(cells, goals)
        runs, cpu = goal_runs(master, probe, goal_list[:CPU_GOALS])
        set_real_time_factor(factor)
        print(f"    at factor {factor}:", flush=True)
        return amcl, goal_list, runs + goal_runs(master, probe, goal_list[CPU_GOALS:], CPU_GOALS + 1)[0], cpu
    (amcl_m, amcl_rad), goal_list, runs, cpu = _session(1, measure)
    fastest = highest_factor()
    reached = [r for r in runs if r["text"] == "Goal reached."]
    print(f"    amcl after 2 m: {amcl_m:.3f} m, {math.degrees(amcl_rad):.2f} deg", flush=True)
    pairs = [(g, r) for g, r in zip(goal_list, runs) if r["text"] == "Goal reached."]
    return [
        (f"navigation: random goals reached (turtlebot3_world, {len(runs)}, factor {factor})", len(reached) / len(runs),
         "", 0.95, ">="),
        ("navigation: path driven / shortest grid path, median",
         _median(r["driven"] / g[3] for g, r in pairs), "", 1.2, "<="),
        ("navigation: path driven / shortest grid path, worst",
         max((r["driven"] / g[3] for g, r in pairs), default=math.inf), "", 1.2, "<="),
        ("navigation: path driven / cheapest grid path (navfn's cost), worst",
         max((r["driven"] / g[4] for g, r in pairs), default=math.inf), "", 1.2, "<="),
        ("navigation: time to goal / shortest path at 0.26 m/s, median",
         _median(r["waited"] / (g[3] / MAX_VEL_M_S) for g, r in pairs), "", 2.0, "<="),
        ("navigation: closest approach of anything to the body", min(r["clearance"] for r in runs), "m", 0.02,
         ">="),
        ("amcl: position error after 2 m from 0.3 m / 15 deg off", amcl_m, "m", 0.05, "<="),
        ("amcl: yaw error after 2 m from 0.3 m / 15 deg off", math.degrees(amcl_rad), "deg", 3.0, "<="),
        ("amcl CPU at real time (per sim second, navigating)", cpu["/amcl"], "%", 15.0, "<="),
        ("move_base CPU at real time (per sim second, navigating)", cpu["/move_base"], "%", 25.0, "<="),
        (f"navigation: highest real-time factor with {SWEEP_GOALS} goals all reached", fastest, "x", 10, ">="),
    ]


if __name__ == "__main__":
    for row in run(*(int(arg) for arg in sys.argv[1:3])):
        print(row)
