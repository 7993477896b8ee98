"""Hands-off exploration of turtlebot3_world as a course runs it: `roslaunch turtlebot3_slam turtlebot3_slam.launch`,
turtlebot3_navigation's move_base.launch and `roslaunch explore_lite explore.launch`, and nothing else driving
(exploration.py). explore must map at least 90 % of the world's free space, without contact, and stop with
"Exploration stopped.", leaving move_base without a goal and its own node running.

At REAL_TIME_FACTOR 5: at 10 (27 s of sim time, 29 s wall from the first launch to the stop on an idle machine)
the robot touched a pillar in two runs of six at load 12-20 (closest approach 0.001 m): move_base's commands come
late at that factor (test_goal_reaching). Exploration does not need every goal reached, only the frontiers seen.
"""
import math

import pytest

from roslab import nav_goals, wait_until

from . import exploration

REAL_TIME_FACTOR = 5
COVERAGE = 0.90
CONTACT_MARGIN_M = 0.02
EXPLORE_TIMEOUT_S = 300   # wall
START_UP = ("Waiting for costmap to become available, topic: map", "Waiting to connect to move_base server",
            exploration.CONNECTED)
ACTIVE_STATUSES = (0, 1, 6, 7)   # PENDING, ACTIVE, PREEMPTING, RECALLING


@pytest.fixture(scope="module")
def explored(ros_master):
    """(explore's launch process, the probe, the closest approach on /scan), once explore has stopped."""
    explore, probe = exploration.start_exploration(
        ros_master, REAL_TIME_FACTOR, (("/scan", "sensor_msgs/LaserScan"),
                                       ("/move_base/status", "actionlib_msgs/GoalStatusArray"),
                                       ("/explore/frontiers", "visualization_msgs/MarkerArray")))
    clearance = math.inf

    def stopped():
        nonlocal clearance
        clearance = min(clearance, nav_goals.closest_clearance_m([e["msg"] for e in probe.take("/scan")]))
        return exploration.STOPPED in explore.output()
    wait_until(stopped, EXPLORE_TIMEOUT_S, "explore to log 'Exploration stopped.'", interval_s=1.0)
    return explore, probe, clearance


def test_explore_maps_turtlebot3_world_hands_off_and_stops(explored):
    explore, probe, clearance = explored
    coverage = exploration.coverage(exploration.current_map(), exploration.world_free_cells())
    assert coverage >= COVERAGE, (coverage, explore.output()[-3000:])
    assert clearance >= CONTACT_MARGIN_M, (clearance, coverage)
    output = explore.output()
    lines = [line.split("]: ", 1)[-1] for line in output.splitlines()]
    assert [line for line in lines if line in START_UP] == list(START_UP)
    assert "Traceback" not in output
    assert probe.take("/explore/frontiers"), "no frontier markers"


def test_after_the_stop_move_base_has_no_goal_and_explore_stays_up(explored):
    explore, probe, _ = explored
    probe.take("/move_base/status")
    status = probe.wait_for_message("/move_base/status", 20)
    assert not [goal for goal in status["status_list"] if goal["status"] in ACTIVE_STATUSES], status
    assert explore.running()
