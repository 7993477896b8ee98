"""The navigation stack the navigation tests and tests/bench/nav_bench.py drive: turtlebot3_world (Waffle, headless)
at a given real-time factor, then navigation.launch (map_server on a map drawn from the world, amcl started at
SPAWN, move_base with turtlebot3's parameters), and a probe subscribed to the topics the caller reads."""
from pathlib import Path

from roslab import wait_for_service, wait_for_topic

from . import world_map

NAVIGATION_LAUNCH = Path(__file__).resolve().parent / "navigation.launch"
WORLD_LAUNCH = ("turtlebot3_gazebo", "turtlebot3_world.launch")
SPAWN = (-2.0, -0.5)   # turtlebot3_world.launch's spawn point, where amcl starts


def turtlebot3_world_cells():
    """The map of turtlebot3_world that the stack serves (world_map's cells)."""
    return world_map.world_cells("turtlebot3_world", SPAWN)


def start_navigation(master, map_folder, cells, factor, topics, world_launch=WORLD_LAUNCH, spawn=SPAWN):
    """Start the simulator (`world_launch`: (package, launch file), spawning the robot at `spawn` (x, y)) and the
    stack with amcl started there on `master`; returns a probe subscribed to `topics` ((name, type) pairs), started
    after the simulator set /use_sim_time, so its now() and sleep_sim are sim time."""
    map_file = world_map.write_map(map_folder, "map", cells)
    master.roslaunch(*world_launch, "gui:=false", "model:=waffle", f"real_time_factor:={factor}")
    wait_for_service(master.uri, "/gazebo/get_model_state", 60)
    probe = master.probe()
    master.start(["roslaunch", "--wait", str(NAVIGATION_LAUNCH), f"map_file:={map_file}",
                  f"initial_pose_x:={spawn[0]}", f"initial_pose_y:={spawn[1]}"], "navigation")
    wait_for_topic(master.uri, "/move_base/status", 120)
    for topic, kind in topics:
        probe.subscribe(topic, kind)
    return probe
