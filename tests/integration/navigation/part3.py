"""COM2009 Part 3 end to end, the course's commands in the course's order, shared by test_part3 and
tests/bench/part3_bench.py:

1. `roslaunch tuos_simulations nav_world.launch` and `roslaunch turtlebot3_slam turtlebot3_slam.launch`, the robot
   driven round nav_world by a script on /cmd_vel (the SLAM tests' route_driver.py) where a student uses teleop;
2. `rosrun map_server map_saver -f FOLDER/nav_map`, then both launches ended (Ctrl-C);
3. `roslaunch part3_navigation.launch map_file:=FOLDER/nav_map.yaml` (the course's navigation.launch: nav_world,
   map_server, amcl from the START zone, move_base, rviz);
4. for each zone A-D: `rostopic pub /move_base_simple/goal geometry_msgs/PoseStamped` with the YAML a student gets
   by tab completion, frame 'map', the zone's centre and orientation w 1.0, left running (latched) until
   move_base's result arrives, then ended.

No window opens (DISPLAY is unset for the launches: the world and rviz print one line each instead).
"""
import math
import sys
import time
from pathlib import Path

from roslab import nav_goals, wait_for_service, wait_for_service_gone, wait_for_topic, wait_until

HERE = Path(__file__).resolve().parent
PART3_LAUNCH = HERE / "part3_navigation.launch"
ROUTE_DRIVER = HERE.parent / "turtlebot3_slam" / "route_driver.py"
# nav_world's zone centres (the floor texture's circles, r 0.40 m), in the order the course visits them
ZONES = {"A": (-1.853, -1.758), "B": (1.846, -1.018), "C": (-1.829, 1.133), "D": (1.866, 1.866)}
ZONE_RADIUS_M = 0.40
STARTUP_TIMEOUT_S = 120
DRIVE_TIMEOUT_S = 300
SAVER_TIMEOUT_S = 120
SUCCEEDED = 3


def goal_yaml(x, y):
    """The PoseStamped YAML as tab completion writes it, edited as the course says (frame map, x, y, w 1.0)."""
    return ("header:\n  seq: 0\n  stamp:\n    secs: 0\n    nsecs: 0\n  frame_id: 'map'\npose:\n  position:\n"
            f"    x: {x}\n    y: {y}\n    z: 0.0\n  orientation:\n    x: 0.0\n    y: 0.0\n    z: 0.0\n    w: 1.0")


def _headless(master):
    master.env.pop("DISPLAY", None)
    master.env.pop("WAYLAND_DISPLAY", None)


def map_nav_world(master, folder, factor):
    """Steps 1-2: SLAM of nav_world along the scripted route at `factor`; returns the saved map's YAML path."""
    _headless(master)
    world = master.roslaunch("tuos_simulations", "nav_world.launch", "gui:=false", f"real_time_factor:={factor}")
    wait_for_service(master.uri, "/gazebo/get_model_state", STARTUP_TIMEOUT_S)
    slam = master.roslaunch("turtlebot3_slam", "turtlebot3_slam.launch")
    wait_for_service(master.uri, "/dynamic_map", STARTUP_TIMEOUT_S)
    driver = master.start([sys.executable, str(ROUTE_DRIVER), "nav_world", str(Path(folder) / "route.json")],
                          "route_driver")
    wait_until(lambda: not driver.running(), DRIVE_TIMEOUT_S, "the scripted drive round nav_world")
    assert "done" in driver.output(), driver.output()
    saver = master.start(["rosrun", "map_server", "map_saver", "-f", str(Path(folder) / "nav_map")], "map_saver")
    assert saver.popen.wait(timeout=SAVER_TIMEOUT_S) == 0, saver.output()
    for process in (slam, world):
        process.stop()
    wait_for_service_gone(master.uri, "/gazebo/get_model_state")
    return Path(folder) / "nav_map.yaml"


def start_navigation(master, map_yaml, factor, topics=()):
    """Step 3; returns a probe subscribed to /move_base/result and `topics` ((name, type) pairs), started in the
    new simulator's sim time."""
    _headless(master)
    master.start(["roslaunch", "--wait", str(PART3_LAUNCH), f"map_file:={map_yaml}", "gui:=false",
                  f"real_time_factor:={factor}"], "navigation")
    wait_for_service(master.uri, "/gazebo/get_model_state", STARTUP_TIMEOUT_S)
    wait_for_topic(master.uri, "/move_base/status", STARTUP_TIMEOUT_S)
    probe = master.probe()
    for topic, kind in (("/move_base/result", "move_base_msgs/MoveBaseActionResult"), *topics):
        probe.subscribe(topic, kind)
    return probe


def go_to_zone(master, probe, zone):
    """Step 4 for one zone: {status, text, sim_s, distance} (distance: the simulator's robot from the zone's
    centre once move_base answered; status None when no result came in nav_goals' goal timeout)."""
    x, y = ZONES[zone]
    probe.take("/move_base/result")
    start = probe.now()
    pub = master.start(["rostopic", "pub", "/move_base_simple/goal", "geometry_msgs/PoseStamped", goal_yaml(x, y)],
                       f"goal_{zone}")
    try:
        found = []

        def answered():
            # a simple goal's id is the server's, stamped when it came: a result stamped before this goal is
            # the previous goal's (still running when this one preempted it)
            found.extend(entry for entry in probe.take("/move_base/result")
                         if entry["msg"]["status"]["goal_id"]["stamp"] >= start)
            return bool(found) or probe.now() - start > nav_goals.GOAL_TIMEOUT_SIM_S
        wait_until(answered, nav_goals.GOAL_TIMEOUT_SIM_S * 3 + 60, f"move_base's result for zone {zone}",
                   interval_s=0.2)
    finally:
        pub.stop()
    true_x, true_y, _ = nav_goals.true_pose()
    status = found[0]["msg"]["status"] if found else {"status": None, "text": "no result"}
    return dict(status=status["status"], text=status["text"], sim_s=probe.now() - start,
                distance=math.hypot(true_x - x, true_y - y))


def run_sequence(master, folder, mapping_factor, navigation_factor, log=print):
    """The whole sequence; returns {zone: go_to_zone's dict} and the wall seconds of each part."""
    started = time.monotonic()
    map_yaml = map_nav_world(master, folder, mapping_factor)
    mapped = time.monotonic()
    log(f"    mapped and saved in {mapped - started:.0f} s wall (factor {mapping_factor})")
    probe = start_navigation(master, map_yaml, navigation_factor)
    zones = {}
    for zone in ZONES:
        zones[zone] = go_to_zone(master, probe, zone)
        log(f"    zone {zone}: {zones[zone]}")
    finished = time.monotonic()
    return zones, {"mapping": mapped - started, "navigation": finished - mapped, "total": finished - started}


def reached(result):
    """Whether move_base reported the goal reached with the robot inside the zone's circle."""
    return result["status"] == SUCCEEDED and result["distance"] <= ZONE_RADIUS_M
