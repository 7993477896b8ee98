"""tb3_sim benchmarks for scripts/bench (wall-clock figures; not a test, never asserted).

    source scripts/env.sh && python3 tests/bench/tb3_sim_bench.py

Measures, each on a private roscore with the simulator started by its launch file (headless):
- real-time factor at ~real_time_factor:=0 in turtlebot3_world with /scan and /odom subscribed (target >= 120x);
- CPU of the simulator process at factor 1, same subscriptions, as % of one core (target <= 5%);
- the same two with three robots (multi_turtlebot3.launch in turtlebot3_house, each robot's /scan and /odom
  subscribed): factor 0 (target >= 20x) and CPU at factor 1 (target <= 25%), and factor 0 again with the launch
  file's three robot_state_publishers ended (they, not the simulator, bound the first figure);
- one 360-beam scan in turtlebot3_world, from tb3_sim.tools.benchmark (target <= 0.5 ms);
- wall time from `roslaunch` to the first /scan message (target <= 1.5 s);
- with `rostopic hz` taking the default 1920x1080 /camera/rgb/image_raw at 30 Hz (it subscribes with AnyMsg, so
  it costs no decoding): the real-time factor at factor 1 (target >= 0.95) and the simulator's CPU (<= 100 %,
  one core), in turtlebot3_world and in tuos_simulations' line_following (COM2009 Part 6: the camera draws its
  8 x 8 m marked floor, a pink track on yellow, in perspective in every frame).
`run()` returns the rows [(name, value, unit, target, comparison)] for scripts/bench's table
(`scripts/bench tb3_sim_bench` runs only these).
"""
import os
import signal
import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from roslab import RosMaster, wait_for_service, wait_until  # noqa: E402  (needs the sys.path entry above)
from roslab.graph import node_pid  # noqa: E402
from roslab.processes import cpu_seconds  # noqa: E402
from tb3_sim.tools.benchmark import bench_scan  # noqa: E402

MEASURE_S = 10.0
CAMERA_TOPIC = "/camera/rgb/image_raw"
WORLD_ARGS = ("world:=turtlebot3_world", "x_pos:=-2.0", "y_pos:=-0.5", "gui:=false")
# (launch command, robot namespaces): one robot in turtlebot3_world, multi_turtlebot3's three in the house, or one
# on the line_following course floor.
ONE_ROBOT = (("tb3_sim", "tb3_sim.launch", *WORLD_ARGS), ("",))
THREE_ROBOTS = (("turtlebot3_gazebo", "multi_turtlebot3.launch", "gui:=false"), ("/tb3_0", "/tb3_1", "/tb3_2"))
LINE_FOLLOWING = (("tuos_simulations", "line_following.launch", "gui:=false"), ("",))
# Debian's robot_state_publisher (1.15.2) looks tf_prefix up on the master on every joint_states message, three
# XML-RPC calls each: at 16x with three robots the master alone takes about 60 % of a core and the 2 cores run
# out. Ending the three shows what the simulator itself does with three robots.
THREE_STATE_PUBLISHERS = tuple(f"{namespace}/robot_state_publisher" for namespace in THREE_ROBOTS[1])
ENDED_SETTLE_S = 2.0


def _with_simulator(factor, measure, camera_subscriber=False, robots=ONE_ROBOT):
    """Start roscore + the simulator at `factor` (`robots`: ONE_ROBOT or THREE_ROBOTS) with a probe on each
    robot's /scan and /odom (and, if `camera_subscriber`, `rostopic hz` on the raw camera image); return
    measure(master, probe). The probe starts after the launch file set /use_sim_time, so `probe.now()` is sim
    time."""
    launch, namespaces = robots
    master = RosMaster(Path(tempfile.mkdtemp(prefix="tb3_bench_")))
    try:
        master.roslaunch(*launch, f"real_time_factor:={factor}")
        wait_for_service(master.uri, "/gazebo/get_world_properties", 30)
        probe = master.probe()
        for namespace in namespaces:
            probe.subscribe(f"{namespace}/scan", "sensor_msgs/LaserScan")
            probe.subscribe(f"{namespace}/odom", "nav_msgs/Odometry")
        for namespace in namespaces:
            probe.wait_for_message(f"{namespace}/scan", 30)
        if camera_subscriber:
            hz = master.start(["rostopic", "hz", CAMERA_TOPIC], "rostopic_hz")
            wait_until(lambda: "average rate" in hz.output(), 30, "rostopic hz to see camera images")
        return measure(master, probe)
    finally:
        master.shutdown()


def real_time_factor_unpaced(robots=ONE_ROBOT, ending=()):
    """Sim seconds per wall second at ~real_time_factor:=0 with each robot's /scan and /odom subscribed, once the
    nodes named in `ending` are ended (roslaunch does not restart them)."""
    def measure(master, probe):
        for node in ending:
            os.kill(node_pid(master.uri, node), signal.SIGTERM)
        if ending:
            time.sleep(ENDED_SETTLE_S)
        sim_start, wall_start = probe.now(), time.monotonic()
        time.sleep(MEASURE_S)
        return (probe.now() - sim_start) / (time.monotonic() - wall_start)
    return _with_simulator(0, measure, robots=robots)


def cpu_percent_at_real_time(robots=ONE_ROBOT):
    """CPU of the simulator process at factor 1, % of one core."""
    def measure(master, _probe):
        pid = node_pid(master.uri, "/gazebo")
        cpu_start, wall_start = cpu_seconds(pid), time.monotonic()
        time.sleep(MEASURE_S)
        return 100.0 * (cpu_seconds(pid) - cpu_start) / (time.monotonic() - wall_start)
    return _with_simulator(1, measure, robots=robots)


def _rtf_and_cpu(master, probe):
    """(sim seconds per wall second, simulator CPU in % of one core) over MEASURE_S."""
    pid = node_pid(master.uri, "/gazebo")
    sim_start, cpu_start, wall_start = probe.now(), cpu_seconds(pid), time.monotonic()
    time.sleep(MEASURE_S)
    wall_s = time.monotonic() - wall_start
    return (probe.now() - sim_start) / wall_s, 100.0 * (cpu_seconds(pid) - cpu_start) / wall_s


def launch_to_first_scan_s():
    """Wall seconds from `roslaunch tb3_sim tb3_sim.launch` (master already up) to the first /scan."""
    master = RosMaster(Path(tempfile.mkdtemp(prefix="tb3_bench_")))
    try:
        probe = master.probe()
        probe.subscribe("/scan", "sensor_msgs/LaserScan")
        start = time.time()
        master.roslaunch("tb3_sim", "tb3_sim.launch", *WORLD_ARGS)
        entries = wait_until(lambda: probe.take("/scan"), 30, "the first /scan", interval_s=0.01)
        return entries[0]["wall"] - start
    finally:
        master.shutdown()


def run():
    """[(name, value, unit, target, comparison)] rows; comparison is ">=" or "<=" against target."""
    camera_rtf, camera_cpu = _with_simulator(1, _rtf_and_cpu, camera_subscriber=True)
    floor_rtf, floor_cpu = _with_simulator(1, _rtf_and_cpu, camera_subscriber=True, robots=LINE_FOLLOWING)
    return [
        ("real-time factor at ~real_time_factor:=0 (/scan, /odom subscribed)", real_time_factor_unpaced(), "x",
         120.0, ">="),
        ("CPU at real_time_factor 1 (/scan, /odom subscribed)", cpu_percent_at_real_time(), "% of a core",
         5.0, "<="),
        ("real-time factor at factor 0, 3 robots (multi_turtlebot3, each /scan, /odom subscribed)",
         real_time_factor_unpaced(THREE_ROBOTS), "x", 20.0, ">="),
        ("the same, its 3 robot_state_publishers ended (they load the master: see THREE_STATE_PUBLISHERS)",
         real_time_factor_unpaced(THREE_ROBOTS, ending=THREE_STATE_PUBLISHERS), "x", 20.0, ">="),
        ("CPU at factor 1, 3 robots (multi_turtlebot3, each /scan, /odom subscribed)",
         cpu_percent_at_real_time(THREE_ROBOTS), "% of a core", 25.0, "<="),
        ("one 360-beam scan in turtlebot3_world", bench_scan() * 1e3, "ms", 0.5, "<="),
        ("roslaunch to first /scan", launch_to_first_scan_s(), "s", 1.5, "<="),
        ("real-time factor at factor 1, 1920x1080 camera subscribed", camera_rtf, "x", 0.95, ">="),
        ("CPU at factor 1, 1920x1080 camera subscribed", camera_cpu, "% of a core", 100.0, "<="),
        ("real-time factor at factor 1, 1920x1080 camera subscribed, line_following's marked floor", floor_rtf, "x",
         0.95, ">="),
        ("CPU at factor 1, 1920x1080 camera subscribed, line_following's marked floor", floor_cpu, "% of a core",
         100.0, "<="),
    ]


if __name__ == "__main__":
    from report import print_table
    print_table(run())
