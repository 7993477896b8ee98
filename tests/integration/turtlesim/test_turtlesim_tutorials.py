"""turtlesim's tutorial executables against a real master: turtle_teleop_key on a pseudo-terminal,
mimic with multisim.launch, and draw_square's corners."""
import math
import os
import pty
import termios
import time
import xmlrpc.client

import pytest
import rosgraph
import rospy
from std_srvs.srv import Empty

from roslab import wait_for_service, wait_for_topic, wait_until
from turtlesim.srv import TeleportAbsolute

CENTRE = 5.544444561004639
POSE = "/turtle1/pose"


def master_api(master):
    return rosgraph.Master("/turtlesim_test", master_uri=master.uri)


def connected(master, node, topic):
    """True when `node` has a live connection on `topic` (from its own bus info)."""
    try:
        uri = master_api(master).lookupNode(node)
        _, _, bus_info = xmlrpc.client.ServerProxy(uri).getBusInfo("/turtlesim_test")
    except (rosgraph.MasterError, OSError):
        return False
    return any(entry[4] == topic and entry[5] for entry in bus_info)


def wait_for_connection(master, node, topic, timeout_s=20.0):
    wait_until(lambda: connected(master, node, topic), timeout_s, "{} connected on {}".format(node, topic))


@pytest.fixture(scope="module")
def sim(ros_master, probe):
    process = ros_master.rosrun("turtlesim", "turtlesim_node", "_headless:=true")
    wait_for_service(ros_master.uri, "/reset")
    wait_for_topic(ros_master.uri, POSE)
    probe.subscribe(POSE, "turtlesim/Pose")
    return process


@pytest.fixture
def terminal():
    """A pseudo-terminal: (the keyboard side's fd, the path a node opens as its stdin)."""
    main_fd, tty_fd = pty.openpty()
    yield main_fd, tty_fd
    os.close(main_fd)
    os.close(tty_fd)


def start_on_terminal(master, tty_fd, package, executable, label):
    """rosrun with its stdin on the terminal `tty_fd`; ended by the master's shutdown at the latest."""
    return master.start(["sh", "-c", 'exec rosrun "$1" "$2" < "$0"', os.ttyname(tty_fd), package, executable],
                        label)


def next_pose(probe, predicate=lambda pose: True, topic=POSE, timeout_s=10.0):
    probe.take(topic)
    return probe.wait_for_message(topic, timeout_s, predicate)


def canonical_mode(tty_fd):
    return bool(termios.tcgetattr(tty_fd)[3] & termios.ICANON)


# --- turtle_teleop_key ----------------------------------------------------------------------------

def test_teleop_arrow_keys_drive_turtle1_and_q_restores_the_terminal(ros_master, sim, probe, terminal):
    main_fd, tty_fd = terminal
    master_api(ros_master).setParam("/scale_linear", 0.5)
    rospy.ServiceProxy("/reset", Empty)()
    teleop = start_on_terminal(ros_master, tty_fd, "turtlesim", "turtle_teleop_key", "teleop")
    wait_until(lambda: "Use arrow keys to move the turtle. 'q' to quit." in teleop.output(), 20, "the banner")
    assert "Reading from keyboard\n---------------------------\n" in teleop.output()
    assert not canonical_mode(tty_fd), "raw mode while reading keys"
    wait_for_connection(ros_master, "/teleop_turtle", "/turtle1/cmd_vel")
    os.write(main_fd, b"\x1b[A")
    pose = next_pose(probe, lambda p: p["linear_velocity"] > 0)
    assert (pose["linear_velocity"], pose["angular_velocity"]) == (0.5, 0.0), "scale from /scale_linear"
    os.write(main_fd, b"\x1b[D")
    pose = next_pose(probe, lambda p: p["angular_velocity"] != 0)
    assert (pose["linear_velocity"], pose["angular_velocity"]) == (0.0, 2.0), "scale_angular default 2.0"
    os.write(main_fd, b"\x1b[C")
    assert next_pose(probe, lambda p: p["angular_velocity"] < 0)["angular_velocity"] == -2.0
    os.write(main_fd, b"q")
    assert teleop.popen.wait(timeout=10) == 0
    assert canonical_mode(tty_fd), "the terminal is restored"
    master_api(ros_master).deleteParam("/scale_linear")


def test_teleop_without_a_terminal_says_so_and_exits(ros_master, sim):
    teleop = ros_master.rosrun("turtlesim", "turtle_teleop_key")
    assert teleop.popen.wait(timeout=20) == 1
    output = teleop.output()
    assert "standard input is not one" in output and "Traceback" not in output


def test_teleop_rejects_a_scale_that_is_not_a_number(ros_master, sim, terminal):
    _, tty_fd = terminal
    master_api(ros_master).setParam("/scale_angular", "fast")
    try:
        teleop = start_on_terminal(ros_master, tty_fd, "turtlesim", "turtle_teleop_key", "teleop-bad")
        assert teleop.popen.wait(timeout=20) == 2
    finally:
        master_api(ros_master).deleteParam("/scale_angular")
    assert "/scale_angular must be a finite number, got 'fast'" in teleop.output()
    assert canonical_mode(tty_fd)


# --- multisim and mimic ---------------------------------------------------------------------------

@pytest.fixture(scope="module")
def multisim(ros_master, probe):
    process = ros_master.roslaunch("turtlesim", "multisim.launch")
    for ns in ("/turtlesim1", "/turtlesim2"):
        wait_for_topic(ros_master.uri, ns + "/turtle1/pose", timeout_s=30)
        probe.subscribe(ns + "/turtle1/pose", "turtlesim/Pose")
    return process


def test_multisim_runs_two_sims_named_sim(ros_master, multisim):
    nodes = {node for _, providers in master_api(ros_master).getSystemState()[2] for node in providers}
    assert {"/turtlesim1/sim", "/turtlesim2/sim"} <= nodes
    for ns in ("/turtlesim1", "/turtlesim2"):
        wait_for_service(ros_master.uri, ns + "/spawn")
        assert master_api(ros_master).getParam(ns + "/sim/background_b") == 255


def test_mimic_makes_the_second_sim_follow_the_first(ros_master, multisim, probe):
    ros_master.rosrun("turtlesim", "mimic", "input:=turtlesim1/turtle1", "output:=turtlesim2/turtle1")
    wait_for_connection(ros_master, "/turtle_mimic", "/turtlesim1/turtle1/pose")
    wait_for_connection(ros_master, "/turtle_mimic", "/turtlesim2/turtle1/cmd_vel")
    probe.publish("/turtlesim1/turtle1/cmd_vel", "geometry_msgs/Twist",
                  {"linear": {"x": 2.0}, "angular": {"z": 1.0}})
    time.sleep(1.8)
    leader = next_pose(probe, topic="/turtlesim1/turtle1/pose")
    follower = next_pose(probe, topic="/turtlesim2/turtle1/pose")
    assert math.hypot(leader["x"] - CENTRE, leader["y"] - CENTRE) > 1.0, "the leader moved"
    assert math.hypot(follower["x"] - leader["x"], follower["y"] - leader["y"]) < 0.1
    assert abs(follower["theta"] - leader["theta"]) < 0.05


# --- draw_square ----------------------------------------------------------------------------------

def stop_points(poses):
    """Where the turtle stood still, one point per stop (consecutive stops closer than 0.5 m merge)."""
    points = []
    for pose in poses:
        if pose["linear_velocity"] == 0.0 and pose["angular_velocity"] == 0.0:
            point = (pose["x"], pose["y"])
            if not points or math.dist(point, points[-1]) > 0.5:
                points.append(point)
    return points


def test_draw_square_resets_then_draws_the_2m_square(ros_master, sim, probe):
    rospy.ServiceProxy("/turtle1/teleport_absolute", TeleportAbsolute)(1.0, 1.0, 0.0)
    next_pose(probe, lambda p: (p["x"], p["y"]) == (1.0, 1.0))
    draw_square = ros_master.rosrun("turtlesim", "draw_square")
    poses = []
    expected = [(CENTRE, CENTRE), (CENTRE + 2, CENTRE), (CENTRE + 2, CENTRE + 2), (CENTRE, CENTRE + 2)]

    def enough_corners():
        poses.extend(entry["msg"] for entry in probe.take(POSE))
        after_reset = poses[next((i for i, p in enumerate(poses) if p["x"] == CENTRE), len(poses)):]
        return len(stop_points(after_reset)) >= len(expected) and stop_points(after_reset)
    try:
        corners = wait_until(enough_corners, 40, "draw_square to reach three corners", interval_s=0.5)
    finally:
        draw_square.stop()
    for corner, (x, y) in zip(corners, expected):
        # The tutorial's own tolerance: it stops within 0.1 m of its goal in x and in y.
        assert abs(corner[0] - x) < 0.1 and abs(corner[1] - y) < 0.1, \
            "corner {} is not within 0.1 m of ({:.3f}, {:.3f}) in x and y".format(corner, x, y)
    output = draw_square.log_path.read_text()
    assert "New goal [7.544445 5.544445, 0.000000]" in output
    assert "Reached goal" in output
