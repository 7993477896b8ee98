"""The TurtleBot3 models of turtlebot3_description as the `xacro` command expands them (no master needed): the
original links and joints (ROBOTIS turtlebot3_description, noetic) with their parents, offsets, inertials and
collision shapes; sensor frames composed from base_footprint; the drive, LiDAR, IMU and camera parameters of the
.gazebo.xacro files; visuals from primitive shapes only."""
import math
import subprocess
import xml.etree.ElementTree as ET
from pathlib import Path

import numpy as np
import pytest

REPO_ROOT = Path(__file__).resolve().parents[3]
XACRO = REPO_ROOT / "catkin_ws" / "src" / "compat" / "xacro" / "xacro"
URDF_DIR = REPO_ROOT / "catkin_ws" / "src" / "compat" / "turtlebot3_description" / "urdf"
MODELS = ("burger", "waffle", "waffle_pi")
TOLERANCE = 1e-6

# The original joints: name -> (type, parent, child, xyz (m), rpy (rad)).
CHASSIS_JOINTS = {
    "waffle": {
        "base_joint": ("fixed", "base_footprint", "base_link", (0, 0, 0.010), (0, 0, 0)),
        "wheel_left_joint": ("continuous", "base_link", "wheel_left_link", (0, 0.144, 0.023), (-1.57, 0, 0)),
        "wheel_right_joint": ("continuous", "base_link", "wheel_right_link", (0, -0.144, 0.023), (-1.57, 0, 0)),
        "caster_back_right_joint": ("fixed", "base_link", "caster_back_right_link", (-0.177, -0.064, -0.004),
                                    (-1.57, 0, 0)),
        "caster_back_left_joint": ("fixed", "base_link", "caster_back_left_link", (-0.177, 0.064, -0.004),
                                   (-1.57, 0, 0)),
        "imu_joint": ("fixed", "base_link", "imu_link", (0, 0, 0.068), (0, 0, 0)),
        "scan_joint": ("fixed", "base_link", "base_scan", (-0.064, 0, 0.122), (0, 0, 0)),
    },
    "burger": {
        "base_joint": ("fixed", "base_footprint", "base_link", (0, 0, 0.010), (0, 0, 0)),
        "wheel_left_joint": ("continuous", "base_link", "wheel_left_link", (0, 0.08, 0.023), (-1.57, 0, 0)),
        "wheel_right_joint": ("continuous", "base_link", "wheel_right_link", (0, -0.08, 0.023), (-1.57, 0, 0)),
        "caster_back_joint": ("fixed", "base_link", "caster_back_link", (-0.081, 0, -0.004), (-1.57, 0, 0)),
        "imu_joint": ("fixed", "base_link", "imu_link", (-0.032, 0, 0.068), (0, 0, 0)),
        "scan_joint": ("fixed", "base_link", "base_scan", (-0.032, 0, 0.172), (0, 0, 0)),
    },
}
OPTICAL_RPY = (-1.57, 0, -1.57)
ORIGINAL_JOINTS = {
    "burger": CHASSIS_JOINTS["burger"],
    "waffle": {
        **CHASSIS_JOINTS["waffle"],
        "camera_joint": ("fixed", "base_link", "camera_link", (0.064, -0.065, 0.094), (0, 0, 0)),
        "camera_rgb_joint": ("fixed", "camera_link", "camera_rgb_frame", (0.005, 0.018, 0.013), (0, 0, 0)),
        "camera_rgb_optical_joint": ("fixed", "camera_rgb_frame", "camera_rgb_optical_frame", (0, 0, 0),
                                     OPTICAL_RPY),
        "camera_depth_joint": ("fixed", "camera_link", "camera_depth_frame", (0.005, 0.028, 0.013), (0, 0, 0)),
        "camera_depth_optical_joint": ("fixed", "camera_depth_frame", "camera_depth_optical_frame", (0, 0, 0),
                                       OPTICAL_RPY),
    },
    "waffle_pi": {
        **CHASSIS_JOINTS["waffle"],
        "camera_joint": ("fixed", "base_link", "camera_link", (0.073, -0.011, 0.084), (0, 0, 0)),
        "camera_rgb_joint": ("fixed", "camera_link", "camera_rgb_frame", (0.003, 0.011, 0.009), (0, 0, 0)),
        "camera_rgb_optical_joint": ("fixed", "camera_rgb_frame", "camera_rgb_optical_frame", (0, 0, 0),
                                     OPTICAL_RPY),
    },
}

WHEEL_MASS_KG = 2.8498940e-02
LDS_MASS_KG = 0.114
CASTER_MASS_KG = 0.005
WAFFLE_BASE_MASS_KG = 1.3729096
ORIGINAL_MASSES_KG = {
    "burger": {"base_link": 8.2573504e-01, "wheel_left_link": WHEEL_MASS_KG, "wheel_right_link": WHEEL_MASS_KG,
               "caster_back_link": CASTER_MASS_KG, "base_scan": LDS_MASS_KG},
    "waffle": {"base_link": WAFFLE_BASE_MASS_KG, "wheel_left_link": WHEEL_MASS_KG, "wheel_right_link": WHEEL_MASS_KG,
               "caster_back_left_link": CASTER_MASS_KG, "caster_back_right_link": CASTER_MASS_KG,
               "base_scan": LDS_MASS_KG},
}
ORIGINAL_MASSES_KG["waffle_pi"] = ORIGINAL_MASSES_KG["waffle"]

# Collision shapes: link -> (shape, dimensions (box size, or cylinder (radius, length)), origin xyz).
WHEEL_COLLISION = ("cylinder", (0.033, 0.018), (0, 0, 0))
CASTER_COLLISION = ("box", (0.030, 0.009, 0.020), (0, 0.001, 0))
LDS_COLLISION = ("cylinder", (0.055, 0.0315), (0.015, 0, -0.0065))
WAFFLE_COLLISIONS = {
    "base_link": ("box", (0.266, 0.266, 0.094), (-0.064, 0, 0.047)),
    "wheel_left_link": WHEEL_COLLISION, "wheel_right_link": WHEEL_COLLISION,
    "caster_back_left_link": CASTER_COLLISION, "caster_back_right_link": CASTER_COLLISION,
    "base_scan": LDS_COLLISION,
}
ORIGINAL_COLLISIONS = {
    "burger": {"base_link": ("box", (0.140, 0.140, 0.143), (-0.032, 0, 0.070)),
               "wheel_left_link": WHEEL_COLLISION, "wheel_right_link": WHEEL_COLLISION,
               "caster_back_link": CASTER_COLLISION, "base_scan": LDS_COLLISION},
    "waffle": {**WAFFLE_COLLISIONS, "camera_link": ("box", (0.012, 0.132, 0.020), (0.003, 0.065, 0.007))},
    "waffle_pi": {**WAFFLE_COLLISIONS, "camera_link": ("box", (0.015, 0.030, 0.027), (0.005, 0.011, 0.013))},
}

# Frames in base_footprint, composed through the joints (m).
COMPOSED_POSITIONS = {
    "burger": {"base_scan": (-0.032, 0, 0.182), "imu_link": (-0.032, 0, 0.078),
               "wheel_left_link": (0, 0.08, 0.033), "wheel_right_link": (0, -0.08, 0.033)},
    "waffle": {"base_scan": (-0.064, 0, 0.132), "imu_link": (0, 0, 0.078),
               "wheel_left_link": (0, 0.144, 0.033), "wheel_right_link": (0, -0.144, 0.033),
               "camera_rgb_optical_frame": (0.069, -0.047, 0.117),
               "camera_depth_optical_frame": (0.069, -0.037, 0.117)},
    "waffle_pi": {"base_scan": (-0.064, 0, 0.132), "imu_link": (0, 0, 0.078),
                  "wheel_left_link": (0, 0.144, 0.033), "wheel_right_link": (0, -0.144, 0.033),
                  "camera_rgb_optical_frame": (0.076, 0.0, 0.103)},
}
# URDF joint separation vs the Gazebo drive plugin's (m); wheel radius 0.033 m, diameter 0.066 m for all.
WHEEL_SEPARATION_M = {"burger": (0.160, 0.160), "waffle": (0.288, 0.287), "waffle_pi": (0.288, 0.287)}
WHEEL_RADIUS_M = 0.033


def expand(xacro_file, *args):
    """Run the workspace's `xacro` command on a file; returns the completed process (text)."""
    return subprocess.run([str(XACRO), *args, str(xacro_file)], stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                          text=True, timeout=60)


@pytest.fixture(scope="module")
def urdf():
    """model -> the root element of its expanded URDF."""
    roots = {}
    for model in MODELS:
        result = expand(URDF_DIR / "turtlebot3_{}.urdf.xacro".format(model), "--inorder")
        assert result.returncode == 0, result.stderr
        roots[model] = ET.fromstring(result.stdout)
    return roots


def floats(text):
    return tuple(float(value) for value in text.split())


def origin_of(element):
    """(xyz, rpy) of an element's <origin>, zeros where absent (the URDF default)."""
    origin = element.find("origin")
    if origin is None:
        return (0.0, 0.0, 0.0), (0.0, 0.0, 0.0)
    return floats(origin.get("xyz", "0 0 0")), floats(origin.get("rpy", "0 0 0"))


def joints(root):
    return {joint.get("name"): joint for joint in root.findall("joint")}


def links(root):
    return {link.get("name"): link for link in root.findall("link")}


def rotation(rpy):
    """URDF's fixed-axis roll, pitch, yaw: R = Rz(yaw) Ry(pitch) Rx(roll)."""
    roll, pitch, yaw = rpy
    cr, sr, cp, sp, cy, sy = (math.cos(roll), math.sin(roll), math.cos(pitch), math.sin(pitch), math.cos(yaw),
                              math.sin(yaw))
    rx = np.array([[1, 0, 0], [0, cr, -sr], [0, sr, cr]])
    ry = np.array([[cp, 0, sp], [0, 1, 0], [-sp, 0, cp]])
    rz = np.array([[cy, -sy, 0], [sy, cy, 0], [0, 0, 1]])
    return rz @ ry @ rx


def pose_in_footprint(root, frame):
    """4x4 transform of `frame` in base_footprint, composed through the joints at zero joint angles."""
    parent_joint = {joint.find("child").get("link"): joint for joint in root.findall("joint")}
    pose = np.eye(4)
    while frame != "base_footprint":
        joint = parent_joint[frame]
        xyz, rpy = origin_of(joint)
        step = np.eye(4)
        step[:3, :3] = rotation(rpy)
        step[:3, 3] = xyz
        pose = step @ pose
        frame = joint.find("parent").get("link")
    return pose


def gazebo_plugin(root, filename):
    return next(plugin for plugin in root.iter("plugin") if plugin.get("filename") == filename)


def gazebo_sensor(root, reference):
    gazebo = next(element for element in root.findall("gazebo") if element.get("reference") == reference)
    return gazebo.find("sensor")


@pytest.mark.parametrize("model", MODELS)
def test_the_robot_is_named_after_the_model(urdf, model):
    assert urdf[model].tag == "robot"
    assert urdf[model].get("name") == "turtlebot3_" + model


@pytest.mark.parametrize("model", MODELS)
def test_the_joints_are_the_originals(urdf, model):
    found = joints(urdf[model])
    assert set(found) == set(ORIGINAL_JOINTS[model])
    for name, (kind, parent, child, xyz, rpy) in ORIGINAL_JOINTS[model].items():
        joint = found[name]
        assert (joint.get("type"), joint.find("parent").get("link"), joint.find("child").get("link")) == (
            kind, parent, child), name
        assert origin_of(joint) == (pytest.approx(xyz, abs=TOLERANCE), pytest.approx(rpy, abs=TOLERANCE)), name
        if kind == "continuous":
            assert floats(joint.find("axis").get("xyz")) == (0, 0, 1)


@pytest.mark.parametrize("model", MODELS)
def test_every_link_is_a_joint_child_except_the_root(urdf, model):
    children = {child for _, _, child, _, _ in ORIGINAL_JOINTS[model].values()}
    assert set(links(urdf[model])) == children | {"base_footprint"}


@pytest.mark.parametrize("model", MODELS)
def test_the_masses_are_the_originals(urdf, model):
    masses = {name: float(link.find("inertial/mass").get("value"))
              for name, link in links(urdf[model]).items() if link.find("inertial") is not None}
    assert masses == pytest.approx(ORIGINAL_MASSES_KG[model], abs=TOLERANCE)


def test_the_base_inertia_tensors_are_the_originals(urdf):
    waffle_base = links(urdf["waffle"])["base_link"].find("inertial/inertia")
    assert float(waffle_base.get("izz")) == pytest.approx(1.4612727e-02)
    assert float(waffle_base.get("ixy")) == pytest.approx(-4.7576583e-05)
    burger_base = links(urdf["burger"])["base_link"].find("inertial/inertia")
    assert float(burger_base.get("ixx")) == pytest.approx(2.2124416e-03)


@pytest.mark.parametrize("model", MODELS)
def test_the_collision_shapes_are_the_originals(urdf, model):
    found = {}
    for name, link in links(urdf[model]).items():
        collision = link.find("collision")
        if collision is None:
            continue
        shape = collision.find("geometry")[0]
        size = floats(shape.get("size")) if shape.tag == "box" else (float(shape.get("radius")),
                                                                      float(shape.get("length")))
        found[name] = (shape.tag, pytest.approx(size), pytest.approx(origin_of(collision)[0], abs=TOLERANCE))
    assert found == ORIGINAL_COLLISIONS[model]


@pytest.mark.parametrize("model", MODELS)
def test_sensor_and_wheel_frames_sit_at_the_original_offsets_from_base_footprint(urdf, model):
    for frame, position in COMPOSED_POSITIONS[model].items():
        assert pose_in_footprint(urdf[model], frame)[:3, 3] == pytest.approx(position, abs=TOLERANCE), frame


@pytest.mark.parametrize("model", ("waffle", "waffle_pi"))
def test_the_optical_frame_looks_ahead_with_x_right_and_y_down(urdf, model):
    axes = pose_in_footprint(urdf[model], "camera_rgb_optical_frame")[:3, :3]
    optical_z, optical_x, optical_y = axes[:, 2], axes[:, 0], axes[:, 1]
    assert optical_z == pytest.approx((1, 0, 0), abs=2e-3)    # ahead
    assert optical_x == pytest.approx((0, -1, 0), abs=2e-3)   # right
    assert optical_y == pytest.approx((0, 0, -1), abs=2e-3)   # down


@pytest.mark.parametrize("model", MODELS)
def test_wheel_separation_and_radius(urdf, model):
    left = pose_in_footprint(urdf[model], "wheel_left_link")[:3, 3]
    right = pose_in_footprint(urdf[model], "wheel_right_link")[:3, 3]
    urdf_separation, drive_separation = WHEEL_SEPARATION_M[model]
    assert np.linalg.norm(left - right) == pytest.approx(urdf_separation)
    for wheel in ("wheel_left_link", "wheel_right_link"):
        cylinder = links(urdf[model])[wheel].find("collision/geometry/cylinder")
        assert float(cylinder.get("radius")) == WHEEL_RADIUS_M
    assert left[2] == pytest.approx(WHEEL_RADIUS_M)   # the axle is one radius above the floor
    drive = gazebo_plugin(urdf[model], "libgazebo_ros_diff_drive.so")
    assert float(drive.findtext("wheelSeparation")) == drive_separation
    assert float(drive.findtext("wheelDiameter")) == 2 * WHEEL_RADIUS_M
    assert (drive.findtext("commandTopic"), drive.findtext("odometryTopic"), drive.findtext("robotBaseFrame"),
            drive.findtext("odometrySource"), float(drive.findtext("updateRate"))) == (
        "cmd_vel", "odom", "base_footprint", "world", 30)


@pytest.mark.parametrize("model", MODELS)
def test_lidar_and_imu_parameters_are_the_originals(urdf, model):
    lidar = gazebo_sensor(urdf[model], "base_scan")
    assert (lidar.get("type"), float(lidar.findtext("update_rate"))) == ("ray", 5)
    assert int(lidar.findtext("ray/scan/horizontal/samples")) == 360
    assert (float(lidar.findtext("ray/scan/horizontal/min_angle")),
            float(lidar.findtext("ray/scan/horizontal/max_angle"))) == (0.0, 6.28319)
    assert (float(lidar.findtext("ray/range/min")), float(lidar.findtext("ray/range/max"))) == (0.120, 3.5)
    assert float(lidar.findtext("ray/noise/stddev")) == 0.01
    assert (lidar.findtext("plugin/topicName"), lidar.findtext("plugin/frameName")) == ("scan", "base_scan")
    imu = gazebo_plugin(urdf[model], "libgazebo_ros_imu.so")
    assert (imu.findtext("topicName"), imu.findtext("frameName"), float(imu.findtext("updateRate"))) == (
        "imu", "imu_link", 0)


def test_waffle_camera_is_the_realsense_depth_camera(urdf):
    camera = gazebo_sensor(urdf["waffle"], "camera_rgb_frame")
    assert (camera.get("type"), camera.get("name")) == ("depth", "realsense_R200")
    assert (int(camera.findtext("camera/image/width")), int(camera.findtext("camera/image/height")),
            float(camera.findtext("camera/horizontal_fov"))) == (1920, 1080, 1.3439)
    plugin = camera.find("plugin")
    assert plugin.get("filename") == "libgazebo_ros_openni_kinect.so"
    assert (float(plugin.findtext("updateRate")), plugin.findtext("cameraName"), plugin.findtext("frameName"),
            plugin.findtext("imageTopicName"), plugin.findtext("depthImageTopicName"),
            float(plugin.findtext("pointCloudCutoff"))) == (
        30, "camera", "camera_rgb_optical_frame", "rgb/image_raw", "depth/image_raw", 0.4)


def test_waffle_pi_camera_is_the_raspberry_pi_camera(urdf):
    camera = gazebo_sensor(urdf["waffle_pi"], "camera_rgb_frame")
    assert (camera.get("type"), camera.get("name")) == ("camera", "Pi Camera")
    assert (int(camera.findtext("camera/image/width")), int(camera.findtext("camera/image/height")),
            float(camera.findtext("camera/horizontal_fov"))) == (640, 480, 1.085595)
    assert (float(camera.findtext("camera/clip/near")), float(camera.findtext("camera/clip/far"))) == (0.03, 100)
    plugin = camera.find("plugin")
    assert plugin.get("filename") == "libgazebo_ros_camera.so"
    assert (float(plugin.findtext("updateRate")), plugin.findtext("cameraName"), plugin.findtext("frameName"),
            plugin.findtext("imageTopicName"), plugin.findtext("cameraInfoTopicName")) == (
        30, "camera", "camera_rgb_optical_frame", "rgb/image_raw", "rgb/camera_info")


def test_burger_has_no_camera(urdf):
    assert not any(name.startswith("camera") for name in links(urdf["burger"]))
    assert gazebo_sensor_references(urdf["burger"]) == {"base_scan", "imu_link"}


def gazebo_sensor_references(root):
    return {gazebo.get("reference") for gazebo in root.findall("gazebo") if gazebo.find("sensor") is not None}


@pytest.mark.parametrize("model", MODELS)
def test_visuals_are_coloured_primitive_shapes_without_meshes(urdf, model):
    root = urdf[model]
    assert not list(root.iter("mesh"))
    colours = {material.get("name") for material in root.findall("material") if material.find("color") is not None}
    visuals = [visual for link in root.findall("link") for visual in link.findall("visual")]
    assert len(visuals) >= 5
    for visual in visuals:
        assert visual.find("geometry")[0].tag in ("box", "cylinder", "sphere")
        assert visual.find("material").get("name") in colours


def test_common_properties_defines_pi_and_the_colours():
    root = ET.parse(URDF_DIR / "common_properties.xacro").getroot()
    names = {material.get("name") for material in root.findall("material")}
    assert names == {"black", "dark", "light_black", "blue", "green", "grey", "orange", "brown", "red", "white"}
    result = expand(URDF_DIR / "turtlebot3_burger.urdf.xacro")
    orange = next(material for material in ET.fromstring(result.stdout).findall("material")
                  if material.get("name") == "orange")
    assert floats(orange.find("color").get("rgba")) == pytest.approx((1.0, 108 / 255, 10 / 255, 1.0))
