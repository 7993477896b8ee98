"""`roslaunch turtlebot3_slam turtlebot3_slam.launch` mapping a world while a scripted drive (route_driver.py,
steering by ground truth the SLAM never sees) follows a fixed route at REAL_TIME_FACTOR x real time, one world at a
time on the module's master: turtlebot3_world, turtlebot3_house (each with true odometry), and the course's
nav_world (`roslaunch tuos_simulations nav_world.launch`, COM2009 Part 3) with tb3_sim's odometry error on (2 %
scale, 1 deg/m heading drift). Each map is compared with the world file's true walls (roslab.map_quality):
precision (occupied cells within 0.10 m of a wall) and recall (the wall length within 3 m of the route marked
occupied). In nav_world a second slam_gmapping maps the same scans from the raw odometry alone (minimumScore too
high for any match, so every scan goes in at its odometry pose), and the SLAM's map must be clearly better; with
the simulator paused, map_saver saves the SLAM's map (its PGM and YAML checked against that grid), a student's node
reads the same grid from /map, and map_server serves the saved files back as that grid, whose precision and recall
are the ones judged. In turtlebot3_world: gmapping's map geometry, latched metadata, ~entropy, map->odom at 20 Hz of
sim time, and the node surviving a simulator reset, a teleport and a restarted master.
"""
import json
import math
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
import rosgraph
import rospy
import yaml
from gazebo_msgs.msg import ModelState
from gazebo_msgs.srv import SetModelState
from nav_msgs.srv import GetMap
from std_srvs.srv import Empty

from lab_nav.maps.geometry import MapGeometry
from roslab import RosProcess, map_quality, wait_for_param, wait_for_service, wait_for_service_gone, wait_until
from roslab.map_reading import read_map_as_a_student
from roslab.mapping_routes import ROUTES
from roslab.master import node_path

REAL_TIME_FACTOR = 8
STARTUP_TIMEOUT_S = 60
# After a reset and a teleport the map must still be right, if a few cells less clean than the first one.
SURVIVED_PRECISION = 0.90
ROBOT = "turtlebot3_waffle"
DRIVER = Path(__file__).with_name("route_driver.py")
TOLERANCE_M = 0.10
REACH_M = 3.0
ODOMETRY_ERROR = {"odom_scale_error": 0.02, "odom_heading_drift": math.radians(1.0)}
ODOMETRY_ONLY = "odometry_only"
# gmapping's transform_publish_period default (turtlebot3's gmapping_params.yaml leaves it), and its tf_delay.
TF_PERIOD_S = 0.05
TF_WINDOW_S = 3.0
TF_LAG_S = 1.0
# map_saver's shades: free (0), occupied (100), unknown (-1).
PGM_SHADES = {0: 254, 100: 0, -1: 205}
SETTLED_S = 1.0
SAVER_TIMEOUT_S = 120   # a hang guard: a loaded machine has taken 30 s for one `rosrun map_server map_saver`


def _no_display_env(ros_master):
    env = dict(ros_master.env)
    env.pop("DISPLAY", None)
    env.pop("WAYLAND_DISPLAY", None)
    return env


class Mapping:
    """One mapping session: a world's launch file, turtlebot3_slam.launch (rviz on, no display), optionally the
    odometry-only mapper; all ended by close()."""

    def __init__(self, ros_master, world_name, odometry_error=False):
        self.master = ros_master
        self.world_name = world_name
        self.route = ROUTES[world_name]
        self.odometry_error = odometry_error
        self.processes = []
        try:
            api = rosgraph.Master("/test", master_uri=ros_master.uri)
            for name in ODOMETRY_ERROR:
                api.setParam(f"/gazebo/{name}", ODOMETRY_ERROR[name] if odometry_error else 0.0)
            self.world = self.start(["roslaunch", "--wait", *self.route.launch, "gui:=false",
                                      f"real_time_factor:={REAL_TIME_FACTOR}"], "world", ros_master.env)
            wait_for_service(ros_master.uri, "/gazebo/get_model_state", STARTUP_TIMEOUT_S)
            wait_for_param(ros_master.uri, "/use_sim_time")
            self.slam = self.start(["roslaunch", "--wait", "turtlebot3_slam", "turtlebot3_slam.launch"], "slam",
                                    _no_display_env(ros_master))
            if odometry_error:
                self._start_odometry_only(api)
            wait_for_service(ros_master.uri, "/dynamic_map", STARTUP_TIMEOUT_S)
            wait_until(lambda: _try_map("/dynamic_map") is not None, 30, "the first map")
            self.route_file = ros_master.workdir / f"route-{world_name}.json"
            driver = self.start([sys.executable, str(DRIVER), world_name, str(self.route_file)], "driver",
                                 ros_master.env)
            wait_until(lambda: not driver.running(), 240, "the scripted drive to finish")
            assert "done" in driver.output(), driver.output()
        except BaseException:   # a start that fails (or Ctrl-C) must not leave the simulator running
            self._stop_processes()
            raise

    def start(self, command, label, env):
        """Start `command` with `env` as part of this session (ended by close()), its output in the module's folder."""
        log = self.master.workdir / f"{self.world_name}{'-error' if self.odometry_error else ''}-{label}.log"
        process = RosProcess(command, env, log)
        self.processes.append(process)
        return process

    def _start_odometry_only(self, api):
        config = Path(__file__).resolve().parents[3] / "catkin_ws/src/compat/turtlebot3_slam/config"
        params = yaml.safe_load((config / "gmapping_params.yaml").read_text())
        params.update(base_frame="base_footprint", minimumScore=1e9, transform_publish_period=0.0)
        for name, value in params.items():
            api.setParam(f"/{ODOMETRY_ONLY}/{name}", value)
        self.start(["rosrun", "gmapping", "slam_gmapping", f"__name:={ODOMETRY_ONLY}", "map:=/odometry_map",
                     "map_metadata:=/odometry_map_metadata", "dynamic_map:=/odometry_dynamic_map"],
                    ODOMETRY_ONLY, self.master.env)
        wait_for_service(self.master.uri, "/odometry_dynamic_map", STARTUP_TIMEOUT_S)

    def route_lasers(self):
        return json.loads(self.route_file.read_text())

    def quality(self, grid):
        """(precision, recall) of an OccupancyGrid against the world's walls."""
        values, geometry = _map_arrays(grid)
        walls = map_quality.world_walls(self.route.world_path())
        return (map_quality.precision(values, geometry, walls, TOLERANCE_M),
                map_quality.recall(values, geometry, walls, self.route_lasers(), REACH_M, TOLERANCE_M))

    def _stop_processes(self):
        for process in reversed(self.processes):
            process.stop()
        self.processes = []

    def close(self):
        self._stop_processes()
        # killed_ok: once (a whole-suite run, load ~10) tb3_sim ignored Ctrl-C and SIGTERM as the house session
        # ended and roslaunch killed it, leaving its services registered; the next world's simulator replaces them
        wait_for_service_gone(self.master.uri, "/gazebo/get_model_state", killed_ok=True)


class MappingSessions:
    """The module's mapping sessions, one at a time: asking for another world (or the same with the odometry
    error switched) ends the current one first. A session that failed to start fails again at once."""

    def __init__(self, ros_master):
        self.master = ros_master
        self.current, self.key, self.failure = None, None, None

    def get(self, world_name, odometry_error=False):
        key = (world_name, odometry_error)
        if key != self.key:
            self.close()
            self.key = key
            try:
                self.current = Mapping(self.master, world_name, odometry_error)
            except BaseException as error:
                self.failure = error
                raise
        if self.failure is not None:
            raise self.failure
        return self.current

    def close(self):
        if self.current is not None:
            self.current.close()
        self.current, self.failure = None, None


def _try_map(service):
    try:
        return rospy.ServiceProxy(service, GetMap)().map
    except (rospy.ServiceException, OSError):
        return None


def _settled_map(service):
    """The map `service` returns once it is the same SETTLED_S of wall time apart: with the simulator paused, scans
    sent before the pause may still be on their way to the mapper."""
    last = None

    def settled():
        nonlocal last
        grid = _try_map(service)
        same = last is not None and grid.data == last.data and grid.info == last.info
        last = grid
        return grid if same else None
    return wait_until(settled, 30, f"{service}'s map to settle", interval_s=SETTLED_S)


def _map_stamp():
    grid = _try_map("/dynamic_map")
    return None if grid is None else grid.header.stamp


def _map_arrays(grid):
    info = grid.info
    geometry = MapGeometry(info.resolution, info.width, info.height, info.origin.position.x,
                           info.origin.position.y)
    return np.array(grid.data, dtype=np.int8).reshape(info.height, info.width), geometry


UNAVAILABLE_METHODS = ("cartographer", "hector", "karto", "frontier_exploration")


def test_the_other_slam_methods_map_with_gmapping_and_say_so_in_one_line(ros_master):
    nodes = subprocess.run(["roslaunch", "--nodes", "turtlebot3_slam", "turtlebot3_slam.launch",
                            "slam_methods:=cartographer", "set_base_frame:=base_footprint", "set_odom_frame:=odom",
                            "set_map_frame:=map"], env=ros_master.env, capture_output=True, text=True, timeout=120)
    assert nodes.returncode == 0, nodes.stderr
    assert {"/turtlebot3_slam_gmapping", "/slam_method_notice", "/rviz"} <= set(nodes.stdout.split())
    for method in UNAVAILABLE_METHODS:
        notice = subprocess.run([node_path("turtlebot3_slam", "slam_method_notice"), method], capture_output=True,
                                text=True, timeout=30)
        assert notice.returncode == 0 and notice.stdout == ""
        assert notice.stderr.count("\n") == 1 and "not packaged for Debian" in notice.stderr
        assert f"slam_methods:={method}" in notice.stderr and "maps with gmapping instead" in notice.stderr


@pytest.fixture(scope="module")
def sessions(ros_master):
    sessions = MappingSessions(ros_master)
    yield sessions
    sessions.close()


@pytest.fixture
def world_mapping(sessions):
    return sessions.get("turtlebot3_world")


@pytest.mark.slow
def test_the_world_map_matches_the_true_walls(world_mapping):
    grid = _try_map("/dynamic_map")
    precision, recall = world_mapping.quality(grid)
    print(f"turtlebot3_world: precision {precision:.3f}, recall {recall:.3f}")
    assert precision >= 0.95 and recall >= 0.90
    assert (grid.info.width, grid.info.height, grid.info.resolution) == (384, 384, pytest.approx(0.05))
    assert (grid.info.origin.position.x, grid.info.origin.position.y) == (-10.0, -10.0)
    assert grid.header.frame_id == "map" and set(np.unique(grid.data)) == {-1, 0, 100}


def test_gmappings_latched_metadata_entropy_topic_and_map_to_odom_tf_at_20_hz(world_mapping, ros_master):
    # A probe of this test's own: one left subscribed to /tf would receive it at 8x through the other worlds' runs.
    probe = ros_master.probe()
    try:
        _check_metadata_entropy_and_tf(world_mapping, probe)
    finally:
        probe.stop()


def _check_metadata_entropy_and_tf(world_mapping, probe):
    probe.subscribe("/map_metadata", "nav_msgs/MapMetaData")
    metadata = probe.wait_for_message("/map_metadata", 20)
    assert (metadata["width"], metadata["height"], metadata["origin"]["position"]["x"]) == (384, 384, -10.0)
    published = rosgraph.Master("/test", master_uri=world_mapping.master.uri).getPublishedTopics("/")
    assert ["/turtlebot3_slam_gmapping/entropy", "std_msgs/Float64"] in published
    probe.subscribe("/tf", "tf2_msgs/TFMessage")
    probe.take("/tf")
    start = probe.now()
    probe.sleep_sim(TF_WINDOW_S)
    end = probe.now()
    stamps = sorted(transform["header"]["stamp"] for entry in probe.take("/tf")
                    for transform in entry["msg"]["transforms"]
                    if transform["header"]["frame_id"] == "map" and transform["child_frame_id"] == "odom")
    # One per 0.05 s of sim time (stamped on the tick plus tf_delay), none repeated, none missing, over the window
    # but for the last TF_LAG_S (transforms still on their way, on a loaded machine).
    assert np.allclose(np.diff(stamps), TF_PERIOD_S, atol=1e-6), np.diff(stamps)
    assert stamps[-1] - stamps[0] >= end - start - TF_LAG_S


def test_the_launch_says_where_to_look_without_a_display(world_mapping):
    output = world_mapping.slam.output()
    assert "no display, so rviz is not started" in output and "lab_web web.launch" in output
    assert "Traceback" not in output and "Initialization complete" in output


def test_slam_survives_a_reset_a_teleport_and_a_master_restart(world_mapping, ros_master):
    before = _map_stamp()
    rospy.ServiceProxy("/gazebo/reset_simulation", Empty)()
    wait_until(lambda: _map_stamp() < before, 30, "a map after the clock jumped back")
    state = ModelState(model_name=ROBOT, reference_frame="world")
    state.pose.position.x, state.pose.position.y, state.pose.orientation.w = 0.55, 0.55, 1.0
    assert rospy.ServiceProxy("/gazebo/set_model_state", SetModelState)(state).success
    stamp = _map_stamp()
    wait_until(lambda: _map_stamp() > stamp, 30, "a map after the teleport")
    precision, _ = world_mapping.quality(_try_map("/dynamic_map"))
    print(f"after a reset and a teleport: precision {precision:.3f}")
    assert precision >= SURVIVED_PRECISION
    ros_master.restart_core()
    wait_for_service(ros_master.uri, "/dynamic_map", timeout_s=30)
    assert _try_map("/dynamic_map") is not None
    assert "Traceback" not in world_mapping.slam.output()


@pytest.mark.slow
def test_the_house_map_matches_the_true_walls(sessions):
    house = sessions.get("turtlebot3_house")
    precision, recall = house.quality(_try_map("/dynamic_map"))
    print(f"turtlebot3_house: precision {precision:.3f}, recall {recall:.3f}")
    assert precision >= 0.95 and recall >= 0.90


@pytest.fixture(scope="module")
def saved_nav_world(sessions, tmp_path_factory):
    """nav_world mapped with the odometry error, then with the simulator paused (no scan, so no new map): the
    SLAM's map and the odometry-only one, the map map_saver saved, and what a student's node read from /map."""
    mapping = sessions.get("nav_world", odometry_error=True)
    folder = tmp_path_factory.mktemp("maps")
    rospy.ServiceProxy("/gazebo/pause_physics", Empty)()
    try:
        grid, odometry_grid = _settled_map("/dynamic_map"), _settled_map("/odometry_dynamic_map")
        # As the course saves it: `cd maps; rosrun map_server map_saver -f NAME`.
        saver = mapping.start(["bash", "-c", f"cd {folder} && rosrun map_server map_saver -f nav_world"], "saver",
                               mapping.master.env)
        saver.popen.wait(timeout=SAVER_TIMEOUT_S)
        student = read_map_as_a_student(mapping.master.env)
    finally:
        rospy.ServiceProxy("/gazebo/unpause_physics", Empty)()
    return mapping, grid, odometry_grid, saver, student, folder


@pytest.mark.slow
def test_map_saver_saves_the_nav_world_map_and_a_student_reads_it_from_map(saved_nav_world):
    mapping, grid, _, saver, student, folder = saved_nav_world
    values, _ = _map_arrays(grid)
    assert saver.popen.returncode == 0, saver.output()
    header = f"P5\n# CREATOR: map_saver.cpp 0.050 m/pix\n{grid.info.width} {grid.info.height}\n255\n".encode()
    shades = np.vectorize(PGM_SHADES.get)(values[::-1]).astype(np.uint8)
    assert (folder / "nav_world.pgm").read_bytes() == header + shades.tobytes()
    assert (folder / "nav_world.yaml").read_text() == (
        "image: nav_world.pgm\nresolution: 0.050000\norigin: [-10.000000, -10.000000, 0.000000]\nnegate: 0\n"
        "occupied_thresh: 0.65\nfree_thresh: 0.196\n\n")
    assert student["grid"] == values.tolist() and student["origin"] == [-10.0, -10.0]
    assert student["walls"] == int((values == 100).sum()) > 0


@pytest.mark.slow
def test_map_server_serves_the_saved_map_back_and_slam_beats_the_drifting_odometry_alone(saved_nav_world):
    mapping, grid, odometry_grid, _, _, folder = saved_nav_world
    # Beside the SLAM's /map, so under other names.
    mapping.start([node_path("map_server", "map_server"), str(folder / "nav_world.yaml"), "map:=/saved_map",
                    "map_metadata:=/saved_map_metadata", "static_map:=/saved_static_map"], "map_server",
                   mapping.master.env)
    wait_for_service(mapping.master.uri, "/saved_static_map", STARTUP_TIMEOUT_S)
    served = _try_map("/saved_static_map")
    assert served.data == grid.data and served.info.origin == grid.info.origin
    assert (served.info.width, served.info.height) == (grid.info.width, grid.info.height)
    slam, odometry = mapping.quality(served), mapping.quality(odometry_grid)
    print(f"nav_world with odometry error: SLAM precision {slam[0]:.3f} recall {slam[1]:.3f}; "
          f"odometry alone precision {odometry[0]:.3f} recall {odometry[1]:.3f}")
    assert slam[0] >= 0.90 and slam[1] >= 0.85
    assert odometry[0] <= slam[0] - 0.1
