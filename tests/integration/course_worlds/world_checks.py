"""What every course-world launch file must show, as tests the course-world modules import: the original's
model names and spawn pose in /gazebo/model_states, and /scan reading the original's walls and pillars."""
import math
import statistics
from typing import NamedTuple, Tuple

import pytest
import rospy
from gazebo_msgs.msg import ModelState
from gazebo_msgs.srv import SetModelState
from std_srvs.srv import Empty

from roslab import TopicProbe, wait_until
from roslab.scan_geometry import beam_angle, beam_index, expected_range, scan_origin

from .conftest import ROBOT_NAME

SCANS_AVERAGED = 5                 # the scan's noise has sigma 0.01 m: five scans make 2 cm a wide margin
SCAN_TOLERANCE_M = 0.02
CAMERA_IN_BASE = (0.069, -0.047, 0.117)   # camera_rgb_frame in base_footprint (turtlebot3_waffle.urdf.xacro)
FLOOR_LIGHTING = 0.896                     # the course floors' material under their sun, as tb3_sim renders them
COLOUR_TOLERANCE = 40                      # per channel, over a 3 x 3 pixel patch's mean
LOADED_WAIT_S = 60.0                       # wall seconds for a frame: a few sim seconds on a machine under load 30


class FloorView(NamedTuple):
    """The robot put at `pose` (x, y, yaw) sees the floor point `point` (x, y) in its camera image, where the
    camera's projection puts it, in the floor art's colour `rgb` (as Gazebo lights the course floors: 0.896 x)."""

    pose: Tuple[float, float, float]
    point: Tuple[float, float]
    rgb: Tuple[int, int, int]


class WorldCase(NamedTuple):
    """One `roslaunch package launch_file *args`: the robot's expected spawn pose (x, y, yaw), the model names
    /gazebo/model_states lists before the robot, `beams`: world-frame bearings in degrees whose /scan
    reading must be the nearest hit among `shapes` (roslab.scan_geometry Rects and Discs from the original's
    numbers; inf beyond 3.5 m or with no shape), and `floor_views` the camera must show."""

    package: str
    launch_file: str
    args: Tuple[str, ...]
    spawn: Tuple[float, float, float]
    models: Tuple[str, ...]
    beams: Tuple[float, ...]
    shapes: tuple = ()
    floor_views: Tuple[FloorView, ...] = ()

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


def at_spawn(case, pose):
    """True if `pose` (x, y, yaw) is the case's spawn pose within 1 mm and 1 mrad."""
    x, y, yaw = pose
    return (math.hypot(x - case.spawn[0], y - case.spawn[1]) < 1e-3
            and abs(math.remainder(yaw - case.spawn[2], 2 * math.pi)) < 1e-3)


def test_models_are_the_originals_and_the_robot_stands_at_the_spawn_pose(case, world):
    poses = model_states(world)
    # tb3_sim lists its ground_plane in every world; Gazebo does where the world file includes one.
    listed = [n for n in poses if n != "ground_plane" or "ground_plane" in case.models]
    assert listed == [*case.models, ROBOT_NAME]
    assert at_spawn(case, poses[ROBOT_NAME]), (case.spawn, poses)


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


def image_pixel(camera_info, robot_pose, point):
    """(column, row) where the camera of a robot at `robot_pose` sees the floor point `point` (camera_info's K)."""
    x, y, yaw = robot_pose
    c, s = math.cos(yaw), math.sin(yaw)
    camera = (x + CAMERA_IN_BASE[0] * c - CAMERA_IN_BASE[1] * s, y + CAMERA_IN_BASE[0] * s + CAMERA_IN_BASE[1] * c)
    dx, dy = point[0] - camera[0], point[1] - camera[1]
    ahead, left = dx * c + dy * s, -dx * s + dy * c
    fx, cx, fy, cy = camera_info["K"][0], camera_info["K"][2], camera_info["K"][4], camera_info["K"][5]
    return cx - fx * left / ahead, cy + fy * CAMERA_IN_BASE[2] / ahead


def test_camera_shows_the_floor_art_where_the_projection_puts_it(case, world, tmp_path):
    if not case.floor_views:
        return
    world.subscribe("/camera/rgb/camera_info", "sensor_msgs/CameraInfo")
    camera_info = world.wait_for_message("/camera/rgb/camera_info", timeout_s=LOADED_WAIT_S)
    image_file = tmp_path / "image.npy"
    world.subscribe("/camera/rgb/image_raw", "sensor_msgs/Image", image_file=image_file)
    try:
        for view in case.floor_views:
            state = ModelState(model_name=ROBOT_NAME)
            state.pose.position.x, state.pose.position.y = view.pose[:2]
            state.pose.orientation.z, state.pose.orientation.w = math.sin(view.pose[2] / 2), math.cos(view.pose[2] / 2)
            assert rospy.ServiceProxy("/gazebo/set_model_state", SetModelState)(state).success
            moved_s = world.now()
            world.wait_for_message("/camera/rgb/image_raw", timeout_s=LOADED_WAIT_S,
                                   predicate=lambda m: m["header"]["stamp"] > moved_s + 0.2)
            image = TopicProbe.latest_image(image_file)
            column, row = (int(round(p)) for p in image_pixel(camera_info, view.pose, view.point))
            seen = image[row - 1:row + 2, column - 1:column + 2].reshape(-1, 3).mean(axis=0)
            expected = [FLOOR_LIGHTING * c for c in view.rgb]
            assert seen == pytest.approx(expected, abs=COLOUR_TOLERANCE), (view, column, row, seen)
    finally:
        rospy.ServiceProxy("/gazebo/reset_world", Empty)()
        # /gazebo/model_states carries no stamp, and the probe may still hold messages from before the reset at 10x:
        # the tests after this one must see the robot back where it spawned.
        wait_until(lambda: at_spawn(case, model_states(world).get(ROBOT_NAME, (math.inf,) * 3)), LOADED_WAIT_S,
                   "the robot back at its spawn pose after the reset")
