"""turtlesim_node against a real master: its graph, services (success and failure as rospy and
rosservice see them), motion, rate, walls, pen and color_sensor, background params, snapshot,
and bad input. One headless node (`_headless:=true`, with the replica's snapshot service turned on) serves
the whole module; each test starts from /reset where it needs a known state. The default graph and console
format are in test_turtlesim_parity.py."""
import math
import re
import subprocess
import time

import pytest
import rosgraph
import rospy
import rosservice
from std_srvs.srv import Empty

from roslab import wait_for_service, wait_for_topic, wait_until
from turtlesim.srv import Kill, SetPen, Spawn, TeleportAbsolute, TeleportRelative

WORLD_SIZE = 11.088889122009277
CENTRE = 5.544444561004639
BACKGROUND = (69, 86, 255)
DT = 0.016
PI = 3.14159265
NODE = "/turtlesim"
POSE = "/turtle1/pose"
COLOR = "/turtle1/color_sensor"


def call(service, srv_type, *args):
    return rospy.ServiceProxy(service, srv_type)(*args)


def run(command, master, timeout_s=30):
    result = subprocess.run(command, env=master.env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                            text=True, timeout=timeout_s)
    return result.returncode, result.stdout


def master_api(master):
    return rosgraph.Master("/turtlesim_test", master_uri=master.uri)


@pytest.fixture(scope="module")
def sim(ros_master, probe):
    process = ros_master.rosrun("turtlesim", "turtlesim_node", "_headless:=true", "_snapshot_service:=true")
    wait_for_service(ros_master.uri, "/turtlesim/snapshot")
    wait_for_topic(ros_master.uri, POSE)
    probe.subscribe(POSE, "turtlesim/Pose")
    probe.subscribe(COLOR, "turtlesim/Color")
    return process


@pytest.fixture
def fresh(sim, probe):
    """A reset turtlesim: turtle1 alone at the centre, stopped, default pen, clean canvas."""
    call("/reset", Empty)
    next_pose(probe, lambda p: (p["x"], p["y"], p["theta"]) == (CENTRE, CENTRE, 0.0))
    return sim


def next_pose(probe, predicate=lambda pose: True, topic=POSE, timeout_s=10.0):
    """The first pose published from now on that satisfies `predicate`."""
    probe.take(topic)
    return probe.wait_for_message(topic, timeout_s, predicate)


def next_color(probe, rgb, timeout_s=5.0):
    return next_pose(probe, lambda c: (c["r"], c["g"], c["b"]) == tuple(rgb), COLOR, timeout_s)


def log_count(process, text):
    return process.output().count(text)


def wait_for_log(process, text, timeout_s=5.0):
    wait_until(lambda: text in process.output(), timeout_s, "log line " + repr(text))


def expected_after_ticks(x, y, theta, v, w, ticks):
    """The spec's update rule (section 1.7 c-d), written out independently of the replica."""
    for _ in range(ticks):
        theta = theta + w * DT
        theta -= 2 * PI * math.floor((theta + PI) / (2 * PI))
        x += v * math.cos(theta) * DT
        y += v * math.sin(theta) * DT
    return x, y, theta


def angle_difference(a, b):
    return abs((a - b + math.pi) % (2 * math.pi) - math.pi)


def service_error(callable_, *args):
    with pytest.raises(rospy.ServiceException) as error:
        callable_(*args)
    return str(error.value)


def published_topics(master):
    return dict(master_api(master).getPublishedTopics("/"))


def service_names(master):
    return {name for name, _ in master_api(master).getSystemState()[2]}


# --- graph ----------------------------------------------------------------------------------------

def test_topics_have_the_original_types_and_owner(ros_master, sim):
    types = dict(master_api(ros_master).getTopicTypes())
    assert types["/turtle1/pose"] == "turtlesim/Pose"
    assert types["/turtle1/color_sensor"] == "turtlesim/Color"
    assert types["/turtle1/cmd_vel"] == "geometry_msgs/Twist"
    publishers, subscribers, _ = master_api(ros_master).getSystemState()
    published_by_node = {topic for topic, nodes in publishers if NODE in nodes}
    assert published_by_node == {"/turtle1/pose", "/turtle1/color_sensor", "/rosout"}
    assert NODE in dict(subscribers)["/turtle1/cmd_vel"]


def test_services_have_the_original_types(ros_master, sim):
    expected = {
        "/clear": "std_srvs/Empty", "/reset": "std_srvs/Empty", "/spawn": "turtlesim/Spawn",
        "/kill": "turtlesim/Kill", "/turtle1/set_pen": "turtlesim/SetPen",
        "/turtle1/teleport_absolute": "turtlesim/TeleportAbsolute",
        "/turtle1/teleport_relative": "turtlesim/TeleportRelative",
        "/turtlesim/snapshot": "std_srvs/Empty",   # _snapshot_service:=true; the original has none
        "/turtlesim/get_loggers": "roscpp/GetLoggers",
        "/turtlesim/set_logger_level": "roscpp/SetLoggerLevel",
    }
    provided = {name for name, nodes in master_api(ros_master).getSystemState()[2] if NODE in nodes}
    assert provided == set(expected)
    for name, srv_type in expected.items():
        assert rosservice.get_service_type(name) == srv_type, name


def test_background_params_are_private_ints_with_the_defaults(ros_master, sim):
    params = master_api(ros_master).getParam(NODE)
    assert {name: params[name] for name in ("background_r", "background_g", "background_b")} == {
        "background_r": 69, "background_g": 86, "background_b": 255}
    assert all(type(params[name]) is int for name in ("background_r", "background_g", "background_b"))


def test_start_log_lines(sim):
    output = sim.output()
    assert "[ INFO] [" in output
    assert "]: Starting turtlesim with node name /turtlesim\n" in output
    assert "]: Spawning turtle [turtle1] at x=[5.544445], y=[5.544445], theta=[0.000000]\n" in output


def test_rosrun_finds_one_executable(ros_master):
    code, output = run(["rosrun", "--prefix", "echo", "turtlesim", "turtlesim_node"], ros_master)
    assert code == 0, output
    assert "non-unique" not in output
    assert output.strip().endswith("turtlesim_node")


# --- start state, rate, motion ------------------------------------------------------------------

def test_reset_gives_turtle1_at_the_centre_on_the_background(fresh, probe):
    pose = next_pose(probe)
    assert pose == {"x": CENTRE, "y": CENTRE, "theta": 0.0, "linear_velocity": 0.0,
                    "angular_velocity": 0.0}
    next_color(probe, BACKGROUND)


def test_pose_rate_is_62_5_hz(sim, probe):
    arrivals = [entry["wall"] for entry in probe.collect(POSE, 3.0)]
    rate = (len(arrivals) - 1) / (arrivals[-1] - arrivals[0])
    assert 60.5 <= rate <= 64.5
    colors = probe.take(COLOR)
    assert colors, "color_sensor is published with every pose"


def test_one_twist_moves_turtle1_for_about_one_second(fresh, probe):
    probe.take(POSE)
    probe.publish("/turtle1/cmd_vel", "geometry_msgs/Twist", {"linear": {"x": 2.0}, "angular": {"z": 1.0}})
    time.sleep(1.6)
    poses = [entry["msg"] for entry in probe.take(POSE)]
    moving = [pose for pose in poses if pose["linear_velocity"] > 0.0]
    assert 61 <= len(moving) <= 64, "one Twist lasts the 1 s command timeout (~62 ticks)"
    assert all((p["linear_velocity"], p["angular_velocity"]) == (2.0, 1.0) for p in moving)
    final = poses[-1]
    assert (final["linear_velocity"], final["angular_velocity"]) == (0.0, 0.0)
    x, y, theta = expected_after_ticks(CENTRE, CENTRE, 0.0, 2.0, 1.0, len(moving))
    assert math.hypot(final["x"] - x, final["y"] - y) < 0.05
    assert angle_difference(final["theta"], theta) < 0.02


def test_linear_y_strafes_and_speed_is_a_magnitude(fresh, probe):
    probe.publish("/turtle1/cmd_vel", "geometry_msgs/Twist", {"linear": {"x": -0.3, "y": 0.4}})
    pose = next_pose(probe, lambda p: p["linear_velocity"] > 0)
    assert pose["linear_velocity"] == pytest.approx(0.5)
    time.sleep(1.2)
    pose = next_pose(probe)
    assert pose["x"] < CENTRE and pose["y"] > CENTRE


def test_walls_clamp_with_the_warning(fresh, probe):
    call("/turtle1/teleport_absolute", TeleportAbsolute, 10.9, 3.0, 0.0)
    next_pose(probe, lambda p: p["x"] == pytest.approx(10.9))
    probe.publish("/turtle1/cmd_vel", "geometry_msgs/Twist", {"linear": {"x": 2.0}})
    pose = next_pose(probe, lambda p: p["x"] == WORLD_SIZE and p["linear_velocity"] == 2.0)
    assert pose["y"] == pytest.approx(3.0)
    warning = re.compile(r"\[ WARN\] \[\d+\.\d{9}\]: Oh no! I hit the wall! \(Clamping from \[x=11\.1\d{5}, "
                         r"y=8\.088889\]\)")
    wait_until(lambda: len(warning.findall(fresh.output())) >= 3, 5, "repeated wall warnings")


def test_teleport_out_of_range_x_warns_with_screen_y(fresh, probe):
    call("/turtle1/teleport_absolute", TeleportAbsolute, 20.0, 5.0, 0.0)
    assert next_pose(probe, lambda p: p["x"] == WORLD_SIZE)["y"] == pytest.approx(5.0)
    wait_for_log(fresh, "Oh no! I hit the wall! (Clamping from [x=20.000000, y=6.088889])")


def test_teleport_above_the_top_is_clamped_silently(fresh, probe):
    warnings = log_count(fresh, "Oh no! I hit the wall!")
    call("/turtle1/teleport_absolute", TeleportAbsolute, 2.0, 20.0, 1.0)
    pose = next_pose(probe, lambda p: p["y"] == WORLD_SIZE)
    assert (pose["x"], pose["theta"]) == (2.0, pytest.approx(1.0))
    time.sleep(0.2)
    assert log_count(fresh, "Oh no! I hit the wall!") == warnings


def test_teleport_relative_turns_first_then_moves(fresh, probe):
    call("/turtle1/teleport_relative", TeleportRelative, 1.0, math.pi / 2)
    pose = next_pose(probe, lambda p: p["y"] > CENTRE + 0.5)
    assert (pose["x"], pose["y"], pose["theta"]) == pytest.approx((CENTRE, CENTRE + 1.0, math.pi / 2),
                                                                  abs=1e-5)


# --- spawn and kill -------------------------------------------------------------------------------

def test_spawn_auto_names_follow_the_counter(ros_master, fresh, probe):
    assert call("/spawn", Spawn, 1.0, 2.0, 0.5, "").name == "turtle2"
    wait_for_log(fresh, "Spawning turtle [turtle2] at x=[1.000000], y=[2.000000], theta=[0.500000]")
    assert call("/spawn", Spawn, 3.0, 3.0, 0.0, "").name == "turtle3"
    assert call("/spawn", Spawn, 4.0, 4.0, 0.0, "leo").name == "leo"
    call("/kill", Kill, "turtle3")
    assert call("/spawn", Spawn, 5.0, 5.0, 0.0, "").name == "turtle4", "kill never lowers the counter"
    call("/reset", Empty)
    assert call("/spawn", Spawn, 5.0, 5.0, 0.0, "").name == "turtle2", "reset rewinds the counter"


def test_spawned_turtle_has_its_own_interfaces(ros_master, fresh, probe):
    call("/spawn", Spawn, 1.0, 2.0, 0.0, "leo")
    wait_for_topic(ros_master.uri, "/leo/pose")
    assert published_topics(ros_master)["/leo/color_sensor"] == "turtlesim/Color"
    wait_for_service(ros_master.uri, "/leo/teleport_absolute")
    probe.subscribe("/leo/pose", "turtlesim/Pose")
    call("/leo/teleport_absolute", TeleportAbsolute, 3.0, 4.0, 0.0)
    next_pose(probe, lambda p: (p["x"], p["y"]) == (3.0, 4.0), topic="/leo/pose")


def test_kill_withdraws_the_turtles_interfaces(ros_master, fresh):
    call("/spawn", Spawn, 1.0, 2.0, 0.0, "doomed")
    wait_for_topic(ros_master.uri, "/doomed/pose")
    call("/kill", Kill, "doomed")
    wait_until(lambda: "/doomed/pose" not in published_topics(ros_master), 5, "/doomed/pose withdrawn")
    wait_until(lambda: not {"/doomed/set_pen", "/doomed/teleport_absolute", "/doomed/teleport_relative"}
               & service_names(ros_master), 5, "/doomed services withdrawn")
    assert call("/spawn", Spawn, 1.0, 2.0, 0.0, "doomed").name == "doomed", "the name can be reused"
    wait_for_service(ros_master.uri, "/doomed/set_pen")
    call("/doomed/set_pen", SetPen, 1, 2, 3, 4, 0)


def test_reset_removes_spawned_turtles(ros_master, fresh):
    call("/spawn", Spawn, 1.0, 2.0, 0.0, "gone")
    wait_for_topic(ros_master.uri, "/gone/pose")
    call("/reset", Empty)
    wait_until(lambda: "/gone/pose" not in published_topics(ros_master), 5, "/gone/pose withdrawn")
    wait_for_log(fresh, "Resetting turtlesim.")


def test_killing_turtle1_then_reset_brings_it_back(ros_master, fresh, probe):
    call("/kill", Kill, "turtle1")
    wait_until(lambda: POSE not in published_topics(ros_master), 5, "turtle1 withdrawn")
    call("/reset", Empty)
    next_pose(probe, lambda p: (p["x"], p["y"]) == (CENTRE, CENTRE))


def test_duplicate_spawn_fails_with_an_empty_error(ros_master, fresh):
    call("/spawn", Spawn, 1.0, 2.0, 0.0, "twin")
    assert service_error(call, "/spawn", Spawn, 3.0, 3.0, 0.0, "twin") == \
        "service [/spawn] responded with an error: b''"
    wait_for_log(fresh, "[ERROR] [")
    wait_for_log(fresh, "]: A turtled named [twin] already exists\n")
    assert "Spawning turtle [twin] at x=[3.000000]" not in fresh.output()


def test_invalid_spawn_name_fails_with_roscpps_text(ros_master, fresh):
    text = ("Character [1] is not valid as the first character in Graph Resource Name [1abc].  "
            "Valid characters are a-z, A-Z, / and in some cases ~.")
    assert service_error(call, "/spawn", Spawn, 1.0, 1.0, 0.0, "1abc") == \
        "service [/spawn] responded with an error: b'{}'".format(text)
    wait_for_log(fresh, "Exception thrown while processing service call: " + text)
    assert "/1abc/pose" not in published_topics(ros_master)


def test_unknown_kill_fails_with_an_empty_error(fresh):
    assert service_error(call, "/kill", Kill, "nobody") == "service [/kill] responded with an error: b''"
    wait_for_log(fresh, "Tried to kill turtle [nobody], which does not exist")


def test_rosservice_call_shows_the_empty_error(ros_master, fresh):
    code, output = run(["rosservice", "call", "/kill", "name: 'nobody'"], ros_master)
    assert code != 0
    assert "ERROR: service [/kill] responded with an error: b''" in output
    call("/spawn", Spawn, 1.0, 1.0, 0.0, "dup")
    code, output = run(["rosservice", "call", "/spawn", "{x: 1, y: 1, theta: 0, name: dup}"], ros_master)
    assert code != 0
    assert "ERROR: service [/spawn] responded with an error: b''" in output


def test_rosservice_call_spawn_prints_the_name(ros_master, fresh):
    code, output = run(["rosservice", "call", "/spawn", "2", "2", "0.2", ""], ros_master)
    assert code == 0, output
    assert 'name: "turtle2"' in output


# --- pen, color_sensor, clear, background ---------------------------------------------------------

def test_color_sensor_sees_the_pen_line_until_clear(ros_master, fresh, probe):
    call("/turtle1/set_pen", SetPen, 255, 0, 0, 5, 0)
    call("/turtle1/teleport_absolute", TeleportAbsolute, 2.0, 2.0, 0.0)
    next_pose(probe, lambda p: (p["x"], p["y"]) == (2.0, 2.0))
    call("/turtle1/set_pen", SetPen, 0, 0, 0, 0, 1)
    call("/turtle1/teleport_absolute", TeleportAbsolute, 3.5, 3.5, 0.0)
    next_color(probe, (255, 0, 0))
    call("/clear", Empty)
    next_color(probe, BACKGROUND)
    wait_for_log(fresh, "Clearing turtlesim.")


def test_background_param_takes_effect_on_clear(ros_master, fresh, probe):
    code, output = run(["rosparam", "set", "/turtlesim/background_r", "255"], ros_master)
    assert code == 0, output
    try:
        time.sleep(0.2)
        next_color(probe, BACKGROUND)  # no effect before /clear
        call("/clear", Empty)
        next_color(probe, (255, 86, 255))
    finally:
        master_api(ros_master).setParam("/turtlesim/background_r", 69)
        call("/clear", Empty)
    next_color(probe, BACKGROUND)


def test_moving_with_the_pen_on_draws_behind_the_turtle(fresh, probe):
    call("/turtle1/set_pen", SetPen, 0, 255, 0, 3, 0)
    probe.publish("/turtle1/cmd_vel", "geometry_msgs/Twist", {"linear": {"x": 2.0}})
    next_pose(probe, lambda p: p["x"] > CENTRE + 1.0)
    call("/turtle1/teleport_absolute", TeleportAbsolute, CENTRE + 0.5, CENTRE, 0.0)
    next_color(probe, (0, 255, 0))


# --- snapshot -------------------------------------------------------------------------------------

def read_png(path):
    from PyQt5.QtGui import QImage, qBlue, qGreen, qRed
    image = QImage(str(path))
    assert not image.isNull(), "not a readable PNG: {}".format(path)

    def pixel(x_m, y_m):
        value = image.pixel(round(x_m * 45), round((WORLD_SIZE - y_m) * 45))
        return qRed(value), qGreen(value), qBlue(value)
    return image, pixel


def draw_red_line(probe):
    call("/turtle1/set_pen", SetPen, 255, 0, 0, 5, 0)
    call("/turtle1/teleport_absolute", TeleportAbsolute, 2.0, 2.0, 0.0)
    next_pose(probe, lambda p: (p["x"], p["y"]) == (2.0, 2.0))


def test_snapshot_writes_a_png_with_the_trail(ros_master, fresh, probe, tmp_path):
    draw_red_line(probe)
    path = tmp_path / "view.png"
    master_api(ros_master).setParam("/turtlesim/snapshot_path", str(path))
    call("/turtlesim/snapshot", Empty)
    image, pixel = read_png(path)
    assert (image.width(), image.height()) == (500, 500)
    assert pixel(3.5, 3.5) == (255, 0, 0)
    assert pixel(9.0, 2.0) == BACKGROUND
    assert pixel(2.0, 2.0) != (255, 0, 0), "the turtle sprite is drawn over the trail's end"


def test_teleport_then_clear_at_once_leaves_a_clean_canvas(ros_master, fresh, probe, tmp_path):
    """One script calls teleport_absolute with the pen down, then /clear at once: the original answers service calls
    at the start of its next update, after the teleport has been drawn, so the clear removes the line. Three
    rounds, each pair of calls a few milliseconds apart."""
    set_pen = rospy.ServiceProxy("/turtle1/set_pen", SetPen)
    teleport = rospy.ServiceProxy("/turtle1/teleport_absolute", TeleportAbsolute)
    clear = rospy.ServiceProxy("/clear", Empty)
    set_pen(255, 0, 0, 5, 0)
    path = tmp_path / "view.png"
    master_api(ros_master).setParam("/turtlesim/snapshot_path", str(path))
    for x, y in ((1.0, 1.0), (CENTRE, CENTRE), (1.0, 1.0)):
        teleport(x, y, 0.0)
        clear()
        next_pose(probe, lambda p: (p["x"], p["y"]) == (x, y))
        call("/turtlesim/snapshot", Empty)
        _, pixel = read_png(path)
        assert pixel(3.0, 3.0) == BACKGROUND, "the teleport's line to ({}, {}) survived the clear".format(x, y)


def test_snapshot_default_path_is_in_ros_home(ros_master, fresh, probe):
    master_api(ros_master).deleteParam("/turtlesim/snapshot_path")
    call("/turtlesim/snapshot", Empty)
    read_png(ros_master.workdir / "turtlesim.png")


@pytest.mark.parametrize("value, text", [
    ("/no/such/folder/view.png", "Could not write the snapshot to [/no/such/folder/view.png]"),
    (5, "Parameter /turtlesim/snapshot_path must be a file path (a non-empty string), got 5"),
])
def test_snapshot_to_a_bad_path_fails_with_a_clear_error(ros_master, fresh, value, text):
    master_api(ros_master).setParam("/turtlesim/snapshot_path", value)
    try:
        assert text in service_error(call, "/turtlesim/snapshot", Empty)
    finally:
        master_api(ros_master).deleteParam("/turtlesim/snapshot_path")
    wait_for_log(fresh, text)


# --- bad input ------------------------------------------------------------------------------------

def test_non_finite_values_never_reach_a_turtle(ros_master, fresh, probe):
    nan, inf = float("nan"), float("inf")
    probe.publish("/turtle1/cmd_vel", "geometry_msgs/Twist", {"linear": {"x": nan}, "angular": {"z": 1.0}})
    wait_for_log(fresh, "Ignoring cmd_vel for turtle [turtle1]")
    assert "only finite numbers" in service_error(call, "/spawn", Spawn, nan, 1.0, 0.0, "")
    assert "only finite numbers" in service_error(call, "/spawn", Spawn, 1.0, inf, 0.0, "nanny")
    call("/turtle1/teleport_absolute", TeleportAbsolute, inf, 1.0, 0.0)
    call("/turtle1/teleport_relative", TeleportRelative, 1.0, nan)
    wait_for_log(fresh, "Ignoring teleport_relative for turtle [turtle1]")
    assert fresh.running()
    pose = next_pose(probe)
    assert (pose["x"], pose["y"], pose["theta"]) == (CENTRE, CENTRE, 0.0)
    assert "nanny" not in str(master_api(ros_master).getPublishedTopics("/"))
    assert "Traceback" not in fresh.output()


def test_a_bad_headless_param_is_a_clear_error(ros_master, sim):
    process = ros_master.rosrun("turtlesim", "turtlesim_node", "__name:=bad_sim", "_headless:=maybe")
    assert process.popen.wait(timeout=30) == 2
    assert "Parameter /bad_sim/headless must be true or false, got 'maybe'" in process.output()
    assert "Traceback" not in process.output()


def test_sigint_ends_the_node_cleanly(ros_master, sim):
    process = ros_master.rosrun("turtlesim", "turtlesim_node", "__ns:=/short_lived", "_headless:=true")
    wait_for_topic(ros_master.uri, "/short_lived/turtle1/pose")
    assert process.stop() == 0
    assert "Traceback" not in process.log_path.read_text()


def test_a_turtle_named_like_another_shares_its_names_as_in_roscpp(ros_master, fresh, probe):
    assert call("/spawn", Spawn, 1.0, 1.0, 0.0, "/turtle1").name == "/turtle1"
    wait_for_log(fresh, "Tried to advertise a service that is already advertised in this node "
                        "[/turtle1/set_pen]")
    call("/kill", Kill, "/turtle1")
    call("/turtle1/teleport_absolute", TeleportAbsolute, 3.0, 3.0, 0.0)
    next_pose(probe, lambda p: (p["x"], p["y"]) == (3.0, 3.0))
    assert fresh.running()
