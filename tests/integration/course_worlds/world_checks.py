"""What every course-world launch file must show, as tests the course-world modules import: the original's
model names and spawn pose in /gazebo/model_states, and /scan reading the original's walls and pillars."""
import math
import statistics
from typing import NamedTuple, Tuple

import pytest

from roslab import wait_until
from roslab.scan_geometry import beam_angle, beam_index, expected_range, scan_origin

from .conftest import ROBOT_NAME

SCANS_AVERAGED = 5                 # the scan's noise has sigma 0.01 m: five scans make 2 cm a wide margin
SCAN_TOLERANCE_M = 0.02


class WorldCase(NamedTuple):
    """One `roslaunch package launch_file *args`: the robot's expected spawn pose (x, y, yaw), the model names
    /gazebo/model_states lists before the robot, and `beams`: world-frame bearings in degrees whose /scan
    reading must be the nearest hit among `shapes` (roslab.scan_geometry Rects and Discs from the original's
    numbers; inf beyond 3.5 m or with no shape)."""

    package: str
    launch_file: str
    args: Tuple[str, ...]
    spawn: Tuple[float, float, float]
    models: Tuple[str, ...]
    beams: Tuple[float, ...]
    shapes: tuple = ()

    @property
    def id(self):
        return " ".join((self.launch_file, *self.args))


def model_states(probe):
    """The next /gazebo/model_states message as {name: (x, y, yaw)}, in the message's order."""
    probe.take("/gazebo/model_states")
    message = probe.wait_for_message("/gazebo/model_states")
    poses = {}
    for name, pose in zip(message["name"], message["pose"]):
        q = pose["orientation"]
        yaw = math.atan2(2 * (q["w"] * q["z"] + q["x"] * q["y"]), 1 - 2 * (q["y"] ** 2 + q["z"] ** 2))
        poses[name] = (pose["position"]["x"], pose["position"]["y"], yaw)
    return poses


def mean_scan(probe):
    """The mean of each beam over the next SCANS_AVERAGED scans (inf where any of them reads inf)."""
    probe.subscribe("/scan", "sensor_msgs/LaserScan")
    probe.take("/scan")
    scans = []

    def enough():
        scans.extend(entry["msg"]["ranges"] for entry in probe.take("/scan"))
        return len(scans) >= SCANS_AVERAGED
    wait_until(enough, 30, f"{SCANS_AVERAGED} scans")
    return [statistics.mean(float(scan[i]) for scan in scans[:SCANS_AVERAGED]) for i in range(len(scans[0]))]


def test_models_are_the_originals_and_the_robot_stands_at_the_spawn_pose(case, world):
    poses = model_states(world)
    # tb3_sim lists its ground_plane in every world; Gazebo does where the world file includes one.
    listed = [n for n in poses if n != "ground_plane" or "ground_plane" in case.models]
    assert listed == [*case.models, ROBOT_NAME]
    x, y, yaw = poses[ROBOT_NAME]
    assert (x, y) == pytest.approx(case.spawn[:2], abs=1e-3)
    assert math.remainder(yaw - case.spawn[2], 2 * math.pi) == pytest.approx(0.0, abs=1e-3)


def test_scan_reads_the_originals_walls_and_pillars(case, world):
    x, y, yaw = case.spawn
    origin = scan_origin(x, y, yaw)
    ranges = mean_scan(world)
    for bearing in case.beams:
        beam = beam_index(yaw, math.radians(bearing))
        expected = expected_range(origin, beam_angle(yaw, beam), case.shapes)
        if math.isinf(expected):
            assert math.isinf(ranges[beam]), (bearing, beam, ranges[beam])
        else:
            assert ranges[beam] == pytest.approx(expected, abs=SCAN_TOLERANCE_M), (bearing, beam)
