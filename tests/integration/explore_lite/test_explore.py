"""`roslaunch explore_lite explore.launch` on a real /map from map_server, with the robot's pose from tf's
static_transform_publisher: the start-up lines, the frontier markers, the goals it sends (the cheapest frontier's
centroid first), blacklisting of aborted goals and "Exploration stopped." when none is left.

The action server is a small rospy SimpleActionServer on `move_base` that prints each goal and aborts it, so
that every goal is blacklisted in turn: explore's side of the action is real, the robot does not move. Exploration
with the real move_base and gmapping is tests/integration/navigation/test_exploration.py.
"""
import json
import re
import sys

import numpy as np
import pytest
from PIL import Image

from roslab.waiting import wait_for_topic, wait_until

RESOLUTION = 0.05
UNKNOWN, FREE, WALL = 205, 254, 0   # map_saver's pixel values


def room_pixels():
    """A 45 x 45 cell map (0.05 m cells, origin 0): a free 30 x 30 square (columns and rows 5-34) walled on the
    left and bottom, with a 1.0 m opening in the top wall (columns 10-29) and the right side open: two frontiers,
    the right one (30 cells) and the top one (20 cells)."""
    cells = np.full((45, 45), UNKNOWN, np.uint8)   # [row, col], row 0 at the bottom
    cells[5:35, 5:35] = FREE
    cells[4, 4:36] = WALL
    cells[4:36, 4] = WALL
    cells[35, 4:10] = WALL
    cells[35, 30:36] = WALL
    return cells[::-1]   # the image's top row is the map's last row


STAND_IN_MOVE_BASE = """
import json
import actionlib
import rospy
from move_base_msgs.msg import MoveBaseAction

def execute(goal):
    pose = goal.target_pose
    print(json.dumps({"frame": pose.header.frame_id, "x": pose.pose.position.x, "y": pose.pose.position.y,
                      "w": pose.pose.orientation.w}), flush=True)
    server.set_aborted()

rospy.init_node("move_base")
server = actionlib.SimpleActionServer("move_base", MoveBaseAction, execute, auto_start=False)
server.start()
rospy.spin()
"""


@pytest.fixture(scope="module")
def room_map(ros_master, tmp_path_factory):
    folder = tmp_path_factory.mktemp("room")
    Image.fromarray(room_pixels()).save(folder / "room.pgm")
    (folder / "room.yaml").write_text("image: room.pgm\nresolution: 0.05\norigin: [0.0, 0.0, 0.0]\nnegate: 0\n"
                                      "occupied_thresh: 0.65\nfree_thresh: 0.196\n")
    server = ros_master.rosrun("map_server", "map_server", str(folder / "room.yaml"), "__name:=map_server")
    wait_for_topic(ros_master.uri, "/map")
    yield server
    server.stop()


def goals(process):
    return [json.loads(line) for line in process.output().splitlines() if line.startswith("{")]


def test_explore_launch_sends_the_cheapest_frontier_then_the_next_then_stops(ros_master, room_map):
    probe = ros_master.probe()
    probe.subscribe("/explore/frontiers", "visualization_msgs/MarkerArray", wait_s=0.0)
    pose = ros_master.start(["rosrun", "tf", "static_transform_publisher", "0.4", "0.4", "0", "0", "0", "0", "map",
                             "base_link", "50"], "static_transform_publisher")
    move_base = ros_master.start([sys.executable, "-c", STAND_IN_MOVE_BASE], "move_base")
    explore = ros_master.roslaunch("explore_lite", "explore.launch")
    try:
        wait_until(lambda: "Exploration stopped." in explore.output(), 180, "exploration to stop")
        output = explore.output()
        lines = [re.sub(r"^\[[ A-Z]+\] \[[\d.]+\]: ", "", line) for line in output.splitlines()]
        start_up = ["Waiting for costmap to become available, topic: map", "Waiting to connect to move_base server",
                    "Connected to move_base server"]
        assert [line for line in lines if line in start_up] == start_up
        assert "found 2 frontiers" in lines
        assert lines.count("Adding current goal to black list") == 2
        assert "Traceback" not in output and "init_node" not in output   # explore's debug lines, not rospy's

        right, top = goals(move_base)
        assert (right["frame"], right["w"], top["frame"], top["w"]) == ("map", 1.0, "map", 1.0)
        # the right frontier: 30 cells at x = 1.775 m; the centroid sums 29 of them over 30 (the original's quirk)
        assert right["x"] == pytest.approx(1.775 * 29 / 30)
        assert 0.94 <= right["y"] <= 0.995
        # the top frontier: 20 cells at y = 1.775 m, x from 0.525 to 1.475 m
        assert top["y"] == pytest.approx(1.775 * 19 / 20)
        assert 0.9 <= top["x"] <= 0.98

        # the last array is published just before "Exploration stopped." is logged, and may reach the probe after it
        arrays = []

        def last_array_came():
            arrays.extend(entry["msg"]["markers"] for entry in probe.take("/explore/frontiers"))
            return arrays and [m["color"]["r"] for m in arrays[-1][0::2]] == [1.0, 1.0]
        wait_until(last_array_came, 10, "frontier markers with both frontiers blacklisted (red)")
        first, last = arrays[0], arrays[-1]
        assert [(m["id"], m["type"], m["ns"]) for m in first] == [(0, 8, "frontiers"), (1, 2, "frontiers"),
                                                                  (2, 8, "frontiers"), (3, 2, "frontiers")]
        assert [len(m["points"]) for m in first[0::2]] == [29, 19]
        assert [m["color"]["b"] for m in first[0::2]] == [1.0, 1.0]      # blue: not blacklisted
        assert [m["color"]["r"] for m in last[0::2]] == [1.0, 1.0]       # red: both blacklisted in the end
        assert explore.running()                                         # stopped exploring, node still up
    finally:
        for process in (explore, move_base, pose):
            process.stop()
        probe.stop()


def test_a_bad_parameter_is_an_error_naming_it(ros_master):
    explore = ros_master.rosrun("explore_lite", "explore", "_planner_frequency:=0")
    assert explore.popen.wait(timeout=90) == 1
    assert "~planner_frequency must be a positive number, got 0" in explore.output()
