"""Micro-benchmarks of the core for scripts/bench (wall-clock figures; never used by tests).

Each function returns plain numbers so the caller can print its table of ratios and rates.
"""

import time

from tb3_sim.core.geometry import Pose2D
from tb3_sim.core.lidar import Lidar
from tb3_sim.core.world import World
from tb3_sim.core.world_file import load_world, shipped_world_path

# Where turtlebot3_world.launch spawns the robot (x_pos, y_pos defaults).
TURTLEBOT3_WORLD_SPAWN = Pose2D(-2.0, -0.5, 0.0)


def _turtlebot3_world():
    return World(load_world(shipped_world_path("turtlebot3_world")), TURTLEBOT3_WORLD_SPAWN)


def bench_scan(repeats=2000):
    """Mean wall seconds for one 360-beam scan in turtlebot3_world from the launch spawn pose (target 0.5 ms)."""
    world, lidar = _turtlebot3_world(), Lidar()
    lidar.read(world, world.robot, world.time_s)
    start = time.perf_counter()
    for _ in range(repeats):
        lidar.read(world, world.robot, world.time_s)
    return (time.perf_counter() - start) / repeats


def bench_steps(sim_seconds=20.0):
    """Physics steps per wall second, and the matching real-time factor, with the robot driving a circle
    in turtlebot3_world and no sensors. Returns (steps_per_s, real_time_factor)."""
    world = _turtlebot3_world()
    world.robot.set_command(0.2, 0.3)
    steps = round(sim_seconds / world.step_s)
    start = time.perf_counter()
    for _ in range(steps):
        world.step()
    elapsed = time.perf_counter() - start
    return steps / elapsed, sim_seconds / elapsed


def main():
    """Print the figures; `python -m tb3_sim.tools.benchmark`."""
    scan_s = bench_scan()
    steps_per_s, rtf = bench_steps()
    print(f"360-beam scan, turtlebot3_world: {scan_s * 1e3:.3f} ms")
    print(f"physics steps: {steps_per_s:,.0f} /s (real-time factor {rtf:,.0f}x without sensors)")


if __name__ == "__main__":
    main()
