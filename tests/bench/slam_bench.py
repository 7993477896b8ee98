"""SLAM benchmarks for scripts/bench (wall-clock figures; not a test, never asserted).

    source scripts/env.sh && python3 tests/bench/slam_bench.py [--pictures]

Measures:
- with the algorithm alone (lab_nav.slam fed by tb3_sim's core physics and LiDAR along roslab.mapping_routes'
  routes, no ROS): the median time of one scan match (target <= 15 ms) and of a whole processed scan (match and
  map update, target <= one scan period), and the map's precision and recall against the true walls
  (roslab.map_quality, 0.10 m, 3 m) in turtlebot3_world, turtlebot3_house and the course's nav_world, with true
  odometry, with tb3_sim's odometry error (2 % scale, 1 deg/m heading drift), and that erring odometry alone (no
  matching) for comparison (targets 0.95 / 0.90 without error, 0.90 / 0.85 with it, at most 0.85 / 0.85 for the
  odometry alone: visibly worse);
- on ROS (turtlebot3_world.launch + turtlebot3_slam.launch, headless, the robot driving a circle): the SLAM
  node's CPU at real time with 5 Hz scans (target <= 20 % of a core), and the highest real-time factor of
  FACTORS at which no map update is missed - the largest gap between two maps stays within map_update_interval
  plus one temporalUpdate and two scan periods (target >= 10x).
`--pictures` also writes docs/images/slam_<world>.png, each world's map (with true odometry) for the README.
`run()` returns the rows [(name, value, unit, target, comparison)] for scripts/bench's table.
"""
import math
import statistics
import sys
import tempfile
import time
from pathlib import Path

import numpy as np
import yaml

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from lab_nav.slam import LaserScanData, Slam, params_from_dict  # noqa: E402
from roslab import RosMaster, map_quality, wait_for_param, wait_for_service  # noqa: E402
from roslab.graph import node_pid  # noqa: E402
from roslab.mapping_routes import ROUTES, steer  # noqa: E402
from roslab.processes import cpu_seconds  # noqa: E402
from tb3_sim.core.geometry import Pose2D  # noqa: E402
from tb3_sim.core.lidar import LIDAR_UPDATE_RATE_HZ, Lidar  # noqa: E402
from tb3_sim.core.odometry_error import DriftingOdometry, OdometryErrorModel  # noqa: E402
from tb3_sim.core.world import World  # noqa: E402
from tb3_sim.core.world_file import load_world  # noqa: E402

REPO = Path(__file__).resolve().parents[2]
TB3_PARAMS = yaml.safe_load((REPO / "catkin_ws/src/compat/turtlebot3_slam/config/gmapping_params.yaml").read_text())
ODOMETRY_ERROR = OdometryErrorModel(scale_error=0.02, heading_drift=math.radians(1.0))
LASER_ON_BASE = (-0.064, 0.0, 0.0)
CONTROL_PERIOD_S = 0.05
TOLERANCE_M, REACH_M = 0.10, 3.0
CPU_MEASURE_S = 20.0
FACTORS = (5, 10, 15, 20, 30)
FACTOR_SIM_S = 40.0
CIRCLE = {"linear": {"x": 0.15}, "angular": {"z": 0.3}}
SCAN_PERIOD_S = 1.0 / LIDAR_UPDATE_RATE_HZ
MAX_MAP_GAP_S = TB3_PARAMS["map_update_interval"] + TB3_PARAMS["temporalUpdate"] + 2 * SCAN_PERIOD_S
PICTURE_SCALE = 3
# The erring odometry alone must map visibly worse than the SLAM's targets with that error.
ODOMETRY_ALONE = (0.85, 0.85)


def offline_mapping(world_name, odometry_error=None, matching=True):
    """Drive the world's route in tb3_sim's core with the SLAM fed by the LiDAR at 5 Hz and the (erring)
    odometry. Returns (map values, MapGeometry, laser positions along the route, match seconds, processed-scan
    seconds)."""
    route = ROUTES[world_name]
    world = World(load_world(route.world_path()), Pose2D(*route.spawn))
    robot, lidar = world.robot, Lidar(0)
    params = dict(TB3_PARAMS, base_frame="base_footprint", **({} if matching else {"minimumScore": 1e9}))
    slam = Slam(params_from_dict(params))
    match_s = []
    slam.matcher.match = _timed(slam.matcher.match, match_s)
    odometry = DriftingOdometry(odometry_error or OdometryErrorModel(), 0)
    lasers, processed_s, next_scan_s = [], [], 0.0
    steps = round(CONTROL_PERIOD_S / world.step_s)
    for waypoint in route.waypoints:
        while (command := steer(tuple(robot.pose), waypoint)) is not None:
            robot.set_command(*command)
            for _ in range(steps):
                world.step()
                odom = odometry.pose(robot.pose)
            if world.time_s >= next_scan_s:
                next_scan_s += SCAN_PERIOD_S
                reading = lidar.read(world, robot, world.time_s)
                lasers.append(tuple(robot.scan_pose())[:2])
                scan = LaserScanData(world.time_s, reading.ranges, reading.angle_min, reading.angle_increment,
                                     reading.range_min, reading.range_max)
                start = time.perf_counter()
                if slam.add_scan(scan, tuple(odom), LASER_ON_BASE).processed:
                    processed_s.append(time.perf_counter() - start)
    values, geometry = slam.occupancy()
    return values, geometry, lasers, match_s, processed_s


def _timed(function, durations):
    def timed(*args, **kwargs):
        start = time.perf_counter()
        result = function(*args, **kwargs)
        durations.append(time.perf_counter() - start)
        return result
    return timed


def quality(world_name, values, geometry, lasers):
    walls = map_quality.world_walls(ROUTES[world_name].world_path())
    return (map_quality.precision(values, geometry, walls, TOLERANCE_M),
            map_quality.recall(values, geometry, walls, lasers[::5], REACH_M, TOLERANCE_M))


def save_picture(values, path):
    """The map as map_saver shades it (free 254, occupied 0, unknown 205), cropped to the known cells, y up."""
    from PIL import Image
    rows, cols = np.nonzero(values != -1)
    crop = values[rows.min():rows.max() + 1, cols.min():cols.max() + 1]
    shades = np.full(crop.shape, 205, dtype=np.uint8)
    shades[crop == 0], shades[crop == 100] = 254, 0
    image = Image.fromarray(shades[::-1])
    image.resize((image.width * PICTURE_SCALE, image.height * PICTURE_SCALE), Image.NEAREST).save(path)


def _with_slam(factor, measure):
    """roscore, turtlebot3_world.launch at `factor` and turtlebot3_slam.launch (no rviz), the robot driving a
    circle; returns measure(master, probe)."""
    master = RosMaster(Path(tempfile.mkdtemp(prefix="slam_bench_")))
    try:
        master.roslaunch("turtlebot3_gazebo", "turtlebot3_world.launch", "gui:=false",
                         f"real_time_factor:={factor}")
        wait_for_service(master.uri, "/gazebo/get_model_state", 30)
        wait_for_param(master.uri, "/use_sim_time")
        master.roslaunch("turtlebot3_slam", "turtlebot3_slam.launch", "open_rviz:=false")
        probe = master.probe()
        probe.subscribe("/map_metadata", "nav_msgs/MapMetaData")
        probe.wait_for_message("/map_metadata", 60)
        probe.publish("/cmd_vel", "geometry_msgs/Twist", CIRCLE)
        return measure(master, probe)
    finally:
        master.shutdown()


def slam_cpu_percent_at_real_time():
    def measure(master, _probe):
        pid = node_pid(master.uri, "/turtlebot3_slam_gmapping")
        cpu_start, wall_start = cpu_seconds(pid), time.monotonic()
        time.sleep(CPU_MEASURE_S)
        return 100.0 * (cpu_seconds(pid) - cpu_start) / (time.monotonic() - wall_start)
    return _with_slam(1, measure)


def largest_map_gap_s(factor):
    """The largest sim-time gap between two /map_metadata messages over FACTOR_SIM_S at `factor`."""
    def measure(_master, probe):
        probe.take("/map_metadata")
        probe.sleep_sim(FACTOR_SIM_S, timeout_s=30 + 3 * FACTOR_SIM_S)
        stamps = [entry["ros"] for entry in probe.take("/map_metadata")]
        return max(np.diff(stamps)) if len(stamps) > 1 else math.inf
    return _with_slam(factor, measure)


def highest_factor_keeping_every_map():
    best = 0
    for factor in FACTORS:
        gap = largest_map_gap_s(factor)
        print(f"    factor {factor}: largest gap between maps {gap:.2f} s of sim time (limit {MAX_MAP_GAP_S:.1f})",
              flush=True)
        if gap > MAX_MAP_GAP_S:
            break
        best = factor
    return best


def run(pictures=False):
    rows = []
    match_s, processed_s = [], []
    for world_name in ROUTES:
        for label, error, matching in (("true odometry", None, True), ("odometry error", ODOMETRY_ERROR, True),
                                       ("that odometry alone", ODOMETRY_ERROR, False)):
            values, geometry, lasers, matches, processed = offline_mapping(world_name, error, matching)
            if matching:
                match_s += matches
                processed_s += processed
            if pictures and error is None:
                save_picture(values, REPO / "docs" / "images" / f"slam_{world_name}.png")
            precision, recall = quality(world_name, values, geometry, lasers)
            targets = {None: (0.95, 0.90), ODOMETRY_ERROR: (0.90, 0.85)}[error] if matching else ODOMETRY_ALONE
            comparison = ">=" if matching else "<="
            rows.append((f"{world_name} map precision, {label}", precision, "", targets[0], comparison))
            rows.append((f"{world_name} map recall, {label}", recall, "", targets[1], comparison))
    rows.append(("scan match, median", 1000 * statistics.median(match_s), "ms", 15.0, "<="))
    rows.append(("processed scan (match + map update), median", 1000 * statistics.median(processed_s), "ms",
                 1000 * SCAN_PERIOD_S, "<="))
    rows.append(("SLAM node CPU at real time, 5 Hz scans", slam_cpu_percent_at_real_time(), "%", 20.0, "<="))
    rows.append(("highest factor keeping every map update", highest_factor_keeping_every_map(), "x", 10.0, ">="))
    return rows


if __name__ == "__main__":
    for row in run(pictures="--pictures" in sys.argv):
        print(row)
