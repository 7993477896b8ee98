"""Hands-off exploration as a course runs it, shared by test_exploration and tests/bench/explore_bench.py:
turtlebot3_world.launch (Waffle, headless) at a real-time factor, `roslaunch turtlebot3_slam turtlebot3_slam.launch`
(gmapping; no display, so no rviz), turtlebot3_navigation's move_base.launch and `roslaunch explore_lite
explore.launch`, then nothing but waiting for "Exploration stopped.".

Coverage is the share of the world's free space (world_map's free cells: reachable from the spawn point through
cells no static shape touches) that /map marks free (0), each true free cell looked up by its centre in the SLAM
map's own geometry.
"""
import re

import numpy as np
import rospy
from nav_msgs.srv import GetMap

from lab_nav.maps.geometry import MapGeometry
from roslab import wait_for_param, wait_for_service, wait_until

from . import world_map
from .stack import SPAWN

STOPPED = "Exploration stopped."
CONNECTED = "Connected to move_base server"
BLACKLISTED = "Adding current goal to black list"
STARTUP_TIMEOUT_S = 120


def world_free_cells():
    """World-frame (x, y) arrays of the centres of turtlebot3_world's free cells."""
    rows, cols = np.nonzero(world_map.world_cells("turtlebot3_world", SPAWN) == 0)
    return world_map.GEOMETRY.cell_center(cols, rows)


def coverage(grid, free_xy):
    """The share of the true free cells (x, y arrays) that the OccupancyGrid `grid` marks free."""
    info = grid.info
    geometry = MapGeometry(info.resolution, info.width, info.height, info.origin.position.x, info.origin.position.y)
    values = np.array(grid.data, dtype=np.int8).reshape(info.height, info.width)
    cols, rows = geometry.world_to_cell(*free_xy)
    inside = geometry.contains(cols, rows)
    free = np.zeros(len(cols), bool)
    free[inside] = values[rows[inside], cols[inside]] == 0
    return float(free.mean())


def current_map():
    """gmapping's latest map through /dynamic_map (the caller's ROS_MASTER_URI names the master), or None."""
    try:
        return rospy.ServiceProxy("/dynamic_map", GetMap)().map
    except (rospy.ServiceException, OSError):
        return None


def sim_stamp(output, line):
    """The sim time (s) of explore's first console line ending in `line` (roscpp's format: [wall, sim]), or
    None."""
    found = re.search(r"\[[\d.]+, ([\d.]+)\]: " + re.escape(line) + "$", output, re.MULTILINE)
    return float(found.group(1)) if found else None


def exploring_sim_s(output):
    """Sim seconds from "Connected to move_base server" to the first "Exploration stopped.", or None."""
    start, stop = sim_stamp(output, CONNECTED), sim_stamp(output, STOPPED)
    return None if start is None or stop is None else stop - start


def start_exploration(master, factor, topics=()):
    """Start the world, then SLAM, move_base and explore side by side (explore waits for /map and move_base
    itself, as the original does), on `master`; returns (explore's launch process, whose output holds explore's
    console lines, and a probe subscribed to `topics` ((name, type) pairs) started in sim time)."""
    master.env.pop("DISPLAY", None)          # rviz would open a window: turtlebot3_slam then prints one line
    master.env.pop("WAYLAND_DISPLAY", None)
    master.roslaunch("turtlebot3_gazebo", "turtlebot3_world.launch", "gui:=false", "model:=waffle",
                     f"real_time_factor:={factor}")
    wait_for_service(master.uri, "/gazebo/get_model_state", STARTUP_TIMEOUT_S)
    wait_for_param(master.uri, "/use_sim_time")
    probe = master.probe()
    for topic, kind in topics:
        probe.subscribe(topic, kind, wait_s=0.0)
    master.roslaunch("turtlebot3_slam", "turtlebot3_slam.launch", "model:=waffle")
    master.roslaunch("turtlebot3_navigation", "move_base.launch", "model:=waffle")
    explore = master.roslaunch("explore_lite", "explore.launch")
    wait_until(lambda: CONNECTED in explore.output(), STARTUP_TIMEOUT_S, "explore to connect to move_base")
    return explore, probe
