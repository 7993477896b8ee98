"""tb3_sim as course code sees it: topic names, types, frames and rates (in sim time), /cmd_vel driving the
robot, bad commands ignored. One simulator (tb3_sim.launch, empty world, spawn pose (1, 2, 0.5)) per module."""
import math

import pytest
import rospy
from PyQt5.QtGui import QColor, QImage
from std_srvs.srv import Empty

from roslab import wait_for_service, wait_for_topic, wait_until
from tb3_sim.view.renderer import ROBOT_FILL

SPAWN = (1.0, 2.0, 0.5)


@pytest.fixture(scope="module")
def snapshot_path(tmp_path_factory):
    return tmp_path_factory.mktemp("snapshot") / "view.png"


@pytest.fixture(scope="module")
def sim(ros_master, snapshot_path):
    process = ros_master.roslaunch("tb3_sim", "tb3_sim.launch", "x_pos:=1.0", "y_pos:=2.0", "yaw:=0.5",
                                   f"snapshot_path:={snapshot_path}")
    wait_for_topic(ros_master.uri, "/odom")
    return process


@pytest.fixture(scope="module")
def probe(ros_master, sim):
    """Started after the launch file set /use_sim_time, so the probe's clock is sim time."""
    probe = ros_master.probe()
    for topic, msg_type in (("/odom", "nav_msgs/Odometry"), ("/scan", "sensor_msgs/LaserScan"),
                            ("/clock", "rosgraph_msgs/Clock"), ("/joint_states", "sensor_msgs/JointState"),
                            ("/tf", "tf2_msgs/TFMessage"), ("/tf_static", "tf2_msgs/TFMessage"),
                            ("/imu", "sensor_msgs/Imu")):
        probe.subscribe(topic, msg_type)
    probe.wait_for_message("/scan")
    return probe


def stamps(entries):
    return [entry["msg"]["header"]["stamp"] for entry in entries]


def mean_period(times):
    assert len(times) > 3, times
    return (times[-1] - times[0]) / (len(times) - 1)


def yaw_of(orientation):
    return 2.0 * math.atan2(orientation["z"], orientation["w"])


@pytest.mark.parametrize("topic, msg_type", [
    ("/clock", "rosgraph_msgs/Clock"), ("/odom", "nav_msgs/Odometry"), ("/scan", "sensor_msgs/LaserScan"),
    ("/joint_states", "sensor_msgs/JointState"), ("/tf", "tf2_msgs/TFMessage"), ("/imu", "sensor_msgs/Imu"),
    ("/tf_static", "tf2_msgs/TFMessage"), ("/gazebo/model_states", "gazebo_msgs/ModelStates"),
])
def test_topics_have_gazebo_names_and_types(ros_master, sim, topic, msg_type):
    assert wait_for_topic(ros_master.uri, topic) == msg_type


def test_use_sim_time_is_set(ros_master, sim):
    import rosgraph
    assert rosgraph.Master("/test", master_uri=ros_master.uri).getParam("/use_sim_time") is True


def test_odom_starts_at_the_spawn_pose_with_gazebo_frames_and_covariance(probe):
    odom = probe.wait_for_message("/odom")
    assert (odom["header"]["frame_id"], odom["child_frame_id"]) == ("odom", "base_footprint")
    pose = odom["pose"]["pose"]
    assert pose["position"]["x"] == pytest.approx(SPAWN[0], abs=1e-3)
    assert pose["position"]["y"] == pytest.approx(SPAWN[1], abs=1e-3)
    assert yaw_of(pose["orientation"]) == pytest.approx(SPAWN[2], abs=1e-3)
    covariance = odom["pose"]["covariance"]
    assert [covariance[7 * i] for i in range(6)] == [1e-5, 1e-5, 1e12, 1e12, 1e12, 1e-3]
    assert odom["twist"]["covariance"] == [0.0] * 36


def test_scan_has_gazebo_fields_and_sees_nothing_in_the_empty_world(probe):
    scan = probe.wait_for_message("/scan")
    assert scan["header"]["frame_id"] == "base_scan"
    assert scan["angle_min"] == 0.0
    assert scan["angle_max"] == pytest.approx(6.28319, abs=1e-5)
    assert scan["angle_increment"] == pytest.approx(6.28319 / 359, abs=1e-7)
    assert (scan["time_increment"], scan["scan_time"]) == (0.0, 0.0)
    assert scan["range_min"] == pytest.approx(0.12) and scan["range_max"] == pytest.approx(3.5)
    assert scan["ranges"] == ["inf"] * 360
    assert scan["intensities"] == [0.0] * 360


def test_joint_states_are_the_two_wheels_positions_only(probe):
    joints = probe.wait_for_message("/joint_states")
    assert joints["name"] == ["wheel_left_joint", "wheel_right_joint"]
    assert len(joints["position"]) == 2
    assert joints["velocity"] == [] and joints["effort"] == []


def test_tf_carries_odom_to_base_footprint_with_the_odom_stamp(probe):
    probe.take("/odom")
    probe.take("/tf")
    odom_stamps = set(stamps(probe.collect("/odom", 0.5)))
    transforms = [t for entry in probe.take("/tf") for t in entry["msg"]["transforms"]]
    ours = [t for t in transforms if t["child_frame_id"] == "base_footprint"]
    assert ours and all(t["header"]["frame_id"] == "odom" for t in ours)
    assert odom_stamps & {t["header"]["stamp"] for t in ours}


def test_static_tf_has_the_waffle_frames(probe):
    static = probe.wait_for_message("/tf_static")
    children = {t["child_frame_id"]: t for t in static["transforms"]}
    assert {"base_link", "base_scan", "imu_link"} <= set(children)
    scan = children["base_scan"]
    assert scan["header"]["frame_id"] == "base_link"
    assert (scan["transform"]["translation"]["x"], scan["transform"]["translation"]["z"]) == (-0.064, 0.122)


def test_imu_frame_and_orientation(probe):
    imu = probe.wait_for_message("/imu")
    assert imu["header"]["frame_id"] == "base_footprint"
    assert yaw_of(imu["orientation"]) == pytest.approx(SPAWN[2], abs=1e-3)


@pytest.mark.parametrize("topic, rate_hz", [("/odom", 30.0), ("/joint_states", 30.0), ("/scan", 5.0),
                                            ("/imu", 100.0)])
def test_rates_in_sim_time(probe, topic, rate_hz):
    entries = probe.collect(topic, 2.5)
    assert mean_period(stamps(entries)) == pytest.approx(1.0 / rate_hz, rel=0.02)


def test_clock_ticks_at_100_hz_of_sim_time_on_whole_physics_steps(probe):
    times = [entry["msg"]["clock"] for entry in probe.collect("/clock", 0.5)]
    ticks = [round((b - a) / 0.01, 6) for a, b in zip(times, times[1:])]
    assert all(tick == int(tick) > 0 for tick in ticks), "every /clock is a whole number of 10 ms ticks on"
    assert all(round(t / 0.005, 6) == int(round(t / 0.005, 6)) for t in times), "on whole 5 ms physics steps"
    assert ticks.count(1) > 0.9 * len(ticks), "a busy machine may drop a few /clock messages, not many"


def test_cmd_vel_drives_the_robot_along_its_heading(probe):
    start = probe.wait_for_message("/odom")["pose"]["pose"]["position"]
    probe.publish("/cmd_vel", "geometry_msgs/Twist", {"linear": {"x": 0.2}})
    moving = probe.wait_for_message("/odom", predicate=lambda m: m["twist"]["twist"]["linear"]["x"] > 0.19)
    probe.collect("/odom", 0.5)
    probe.publish("/cmd_vel", "geometry_msgs/Twist", {})
    stopped = probe.wait_for_message("/odom", predicate=lambda m: abs(m["twist"]["twist"]["linear"]["x"]) < 1e-6)
    end = stopped["pose"]["pose"]["position"]
    dx, dy = end["x"] - start["x"], end["y"] - start["y"]
    assert math.hypot(dx, dy) > 0.1
    assert math.atan2(dy, dx) == pytest.approx(SPAWN[2], abs=0.01)
    assert moving["child_frame_id"] == "base_footprint"


def test_nan_and_absurd_cmd_vel_are_ignored_and_the_node_lives_on(probe, sim):
    probe.publish("/cmd_vel", "geometry_msgs/Twist", {"angular": {"z": 0.5}})
    probe.wait_for_message("/odom", predicate=lambda m: m["twist"]["twist"]["angular"]["z"] > 0.49)
    probe.publish("/cmd_vel", "geometry_msgs/Twist", {"linear": {"x": float("nan")}})
    wait_until(lambda: "cmd_vel ignored: linear.x is nan" in sim.output(), 10, "the throttled warning")
    for bad in ({"angular": {"z": float("inf")}}, {"linear": {"x": 1e9}}):
        probe.publish("/cmd_vel", "geometry_msgs/Twist", bad)
        probe.collect("/odom", 0.1)
    held = probe.wait_for_message("/odom")
    assert held["twist"]["twist"]["angular"]["z"] == pytest.approx(0.5, abs=1e-6)
    probe.publish("/cmd_vel", "geometry_msgs/Twist", {})
    assert sim.running()


def test_snapshot_writes_a_png_showing_the_robot(ros_master, sim, probe, snapshot_path):
    wait_for_service(ros_master.uri, "/gazebo/snapshot")
    rospy.ServiceProxy("/gazebo/snapshot", Empty)()
    image = QImage(str(snapshot_path))
    assert not image.isNull()
    robot = ROBOT_FILL.rgb()
    robot_pixels = sum(QColor(image.pixel(c, r)).rgb() == robot
                       for c in range(0, image.width(), 2) for r in range(0, image.height(), 2))
    assert robot_pixels > 100
