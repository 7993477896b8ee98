"""Fuzzing turtlesim_node (issue 8, item 1): every service with generated requests, and turtle1/cmd_vel.

One headless turtlesim_node serves the module; every test starts from /reset. Replies are checked against the
original turtlesim's behaviour as the replica documents it (turtlesim.ros.node, turtlesim.core.simulation): spawn
and kill fail the call the way roscpp does (an empty error for the original's `return false`, roscpp's text for
an invalid name, the replica's text for NaN/inf), teleports and set_pen always succeed, NaN/inf teleports and
commands are ignored. Every pose the node publishes must stay finite and inside the 11.09 m square, and
afterwards the node is the same process, offers every service and printed no traceback.
"""
import math
import re

import numpy
import pytest
import rospy
from hypothesis import given
from hypothesis import strategies as st
from std_srvs.srv import Empty

from roslab import wait_for_service, wait_for_topic
from roslab.fuzz import FUZZ_SETTINGS, MIN_REQUESTS, GraphWatch, ServiceFuzzer
from roslab.fuzz_strategies import float32s, float64s, graph_names, uint8s
from turtlesim.srv import Kill, SetPen, Spawn, TeleportAbsolute, TeleportRelative

WORLD_SIZE = 11.088889122009277
CENTRE = 5.544444561004639
POSE = "/turtle1/pose"
RETURNED_FALSE = "responded with an error: b''"
SERVICES = ["/clear", "/reset", "/spawn", "/kill", "/turtlesim/snapshot", "/turtle1/set_pen",
            "/turtle1/teleport_absolute", "/turtle1/teleport_relative"]


class Turtlesim:
    """The module's node, a probe subscribed to turtle1's pose, and the GraphWatch."""

    def __init__(self, ros_master):
        self.process = ros_master.rosrun("turtlesim", "turtlesim_node", "_headless:=true", "_snapshot_service:=true",
                                         "_snapshot_path:={}".format(ros_master.workdir / "turtlesim.png"))
        for name in SERVICES:
            wait_for_service(ros_master.uri, name)
        wait_for_topic(ros_master.uri, POSE)
        self.probe = ros_master.probe()
        self.probe.subscribe(POSE, "turtlesim/Pose")
        self.watch = GraphWatch(ros_master.uri, ["/turtlesim"], SERVICES, [self.process])

    def reset(self):
        rospy.ServiceProxy("/reset", Empty)()
        return self.next_pose(lambda pose: (pose["x"], pose["y"], pose["theta"]) == (CENTRE, CENTRE, 0.0))

    def next_pose(self, predicate=lambda pose: True, timeout_s=5.0):
        """The first turtle1 pose published from now on that satisfies `predicate`."""
        self.probe.take(POSE)
        return self.probe.wait_for_message(POSE, timeout_s, predicate, interval_s=0.01)

    def assert_poses_inside(self):
        """Every turtle1 pose received since the last call is finite and inside the square."""
        for entry in self.probe.take(POSE):
            assert inside(entry["msg"]), entry["msg"]


@pytest.fixture(scope="module")
def node(ros_master):
    node = Turtlesim(ros_master)
    yield node
    node.watch.assert_alive()


@pytest.fixture
def turtlesim(node):
    node.reset()
    yield node
    node.watch.assert_alive()
    node.reset()


def inside(pose):
    values = [float(pose[key]) for key in ("x", "y", "theta", "linear_velocity", "angular_velocity")]
    return all(math.isfinite(v) for v in values) and 0.0 <= values[0] <= WORLD_SIZE and 0.0 <= values[1] <= WORLD_SIZE


def float32(value):
    with numpy.errstate(over="ignore"):
        return float(numpy.float32(value))


def valid_graph_name(name):
    """roscpp's names::validate as the replica documents it (turtlesim.core.names)."""
    first, rest = set("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ/~"), set(
        "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789/_")
    return name[0] in first and all(char in rest for char in name[1:])


def coordinates():
    """Any float32, or a position inside the square."""
    return st.one_of(float32s(), st.floats(0.0, WORLD_SIZE, width=32))


def test_spawn_fuzzed_names_and_poses(turtlesim):
    """A new turtle exactly when the pose is finite and the name is empty (auto-named), or valid and free;
    otherwise the call fails as roscpp's would. Each new turtle is killed again."""
    fuzzer = ServiceFuzzer("/spawn", Spawn)
    kill = rospy.ServiceProxy("/kill", Kill)

    @FUZZ_SETTINGS
    @given(x=coordinates(), y=coordinates(), theta=float32s(),
           name=st.one_of(st.sampled_from(["", "turtle1", "Leonardo", "a/b", "~private"]), graph_names()))
    def spawn(x, y, theta, name):
        reply = fuzzer.call(x, y, theta, name)
        if not all(math.isfinite(float32(v)) for v in (x, y, theta)):
            assert reply.error and "not all finite" in reply.error
        elif name == "turtle1":
            assert reply.error and reply.error.endswith(RETURNED_FALSE)
        elif name and not valid_graph_name(name):
            assert reply.error and "is not valid" in reply.error
        else:
            assert reply.error is None, reply.error
            assert reply.response.name == name if name else re.fullmatch(r"turtle\d+", reply.response.name)
            kill(reply.response.name)
        turtlesim.assert_poses_inside()

    spawn()
    print("fuzzed /spawn: {} requests".format(fuzzer.calls))
    assert fuzzer.calls >= MIN_REQUESTS
    turtlesim.watch.assert_alive()
    assert rospy.ServiceProxy("/spawn", Spawn)(1.0, 2.0, 0.5, "leo").name == "leo"
    turtlesim.probe.subscribe("/leo/pose", "turtlesim/Pose")
    turtlesim.probe.wait_for_message("/leo/pose", predicate=lambda pose: (pose["x"], pose["y"]) == (1.0, 2.0))
    kill("leo")


def test_kill_fuzzed_names(turtlesim):
    """Only a live turtle can be killed (here `victim`, respawned whenever it was killed); any other name
    fails the call with roscpp's empty error."""
    fuzzer = ServiceFuzzer("/kill", Kill)
    spawn = rospy.ServiceProxy("/spawn", Spawn)
    alive = {"turtle1"}

    @FUZZ_SETTINGS
    @given(name=st.one_of(st.just("victim"), graph_names().filter(lambda name: name != "turtle1")))
    def kill(name):
        if "victim" not in alive:
            spawn(2.0, 2.0, 0.0, "victim")
            alive.add("victim")
        reply = fuzzer.call(name)
        if name in alive:
            assert reply.error is None, reply.error
            alive.remove(name)
        else:
            assert reply.error and reply.error.endswith(RETURNED_FALSE), reply.error

    kill()
    print("fuzzed /kill: {} requests".format(fuzzer.calls))
    assert fuzzer.calls >= MIN_REQUESTS
    turtlesim.watch.assert_alive()
    assert spawn(3.0, 3.0, 0.0, "doomed").name == "doomed"
    assert rospy.ServiceProxy("/kill", Kill)("doomed") is not None


def test_teleport_absolute_fuzzed(turtlesim):
    """A finite target puts turtle1 there (clamped to the square); NaN/inf targets are ignored."""
    fuzzer = ServiceFuzzer("/turtle1/teleport_absolute", TeleportAbsolute)
    last = [(CENTRE, CENTRE)]

    @FUZZ_SETTINGS
    @given(x=coordinates(), y=coordinates(), theta=float32s())
    def teleport(x, y, theta):
        reply = fuzzer.call(x, y, theta)
        assert reply.error is None, reply.error
        if all(math.isfinite(float32(v)) for v in (x, y, theta)):
            last[0] = (min(max(float32(x), 0.0), WORLD_SIZE), min(max(float32(y), 0.0), WORLD_SIZE))
        after = turtlesim.next_pose(lambda pose: (pose["x"], pose["y"]) == pytest.approx(last[0], abs=1e-3))
        assert inside(after)

    teleport()
    print("fuzzed /turtle1/teleport_absolute: {} requests".format(fuzzer.calls))
    assert fuzzer.calls >= MIN_REQUESTS
    turtlesim.watch.assert_alive()
    rospy.ServiceProxy("/turtle1/teleport_absolute", TeleportAbsolute)(2.0, 3.0, 1.0)
    turtlesim.next_pose(lambda pose: (pose["x"], pose["y"], pose["theta"]) == pytest.approx((2.0, 3.0, 1.0)))


def test_teleport_relative_fuzzed(turtlesim):
    """Any relative jump keeps turtle1 finite and inside the square."""
    fuzzer = ServiceFuzzer("/turtle1/teleport_relative", TeleportRelative)

    @FUZZ_SETTINGS
    @given(linear=float32s(), angular=float32s())
    def teleport(linear, angular):
        reply = fuzzer.call(linear, angular)
        assert reply.error is None, reply.error
        assert inside(turtlesim.next_pose())

    teleport()
    print("fuzzed /turtle1/teleport_relative: {} requests".format(fuzzer.calls))
    assert fuzzer.calls >= MIN_REQUESTS
    turtlesim.watch.assert_alive()
    turtlesim.reset()
    rospy.ServiceProxy("/turtle1/teleport_relative", TeleportRelative)(1.0, 0.0)
    turtlesim.next_pose(lambda pose: (pose["x"], pose["y"]) == pytest.approx((CENTRE + 1.0, CENTRE)))


def test_set_pen_fuzzed(turtlesim):
    """Any colour, width and off flag is accepted, and turtle1 keeps being published."""
    fuzzer = ServiceFuzzer("/turtle1/set_pen", SetPen)

    @FUZZ_SETTINGS
    @given(r=uint8s(), g=uint8s(), b=uint8s(), width=uint8s(), off=uint8s())
    def set_pen(r, g, b, width, off):
        assert fuzzer.call(r, g, b, width, off).error is None

    set_pen()
    print("fuzzed /turtle1/set_pen: {} requests".format(fuzzer.calls))
    assert fuzzer.calls >= MIN_REQUESTS
    turtlesim.watch.assert_alive()
    turtlesim.assert_poses_inside()
    assert inside(turtlesim.next_pose())


def test_clear_reset_snapshot_sequences(turtlesim):
    """Any order of /clear, /reset and ~snapshot: every call succeeds; afterwards /reset still puts a new
    turtle1 at the centre. 200 sequences of up to 5 calls (of the 363 there are) give each service its
    MIN_REQUESTS in about 850 calls; up to 8 took 1132, 47 ms each (a snapshot writes a PNG)."""
    fuzzers = {name: ServiceFuzzer(name, Empty) for name in ["/clear", "/reset", "/turtlesim/snapshot"]}

    @FUZZ_SETTINGS
    @given(sequence=st.lists(st.sampled_from(sorted(fuzzers)), min_size=1, max_size=5))
    def control(sequence):
        for name in sequence:
            assert fuzzers[name].call().error is None

    control()
    counts = {name: fuzzer.calls for name, fuzzer in fuzzers.items()}
    print("fuzzed turtlesim clear/reset/snapshot: {}".format(counts))
    assert min(counts.values()) >= MIN_REQUESTS, counts
    turtlesim.watch.assert_alive()
    turtlesim.reset()


def test_cmd_vel_fuzzed_twists_keep_turtle1_finite_and_inside(turtlesim):
    """Every field of turtle1/cmd_vel fuzzed, sane speeds included (turtle1 hits the walls): every pose
    stays finite and inside the square, and a plain command afterwards still drives turtle1."""
    probe = turtlesim.probe
    published = []
    speeds = st.one_of(float64s(), st.floats(-20.0, 20.0))

    @FUZZ_SETTINGS
    @given(values=st.tuples(speeds, speeds, float64s(), float64s(), float64s(), speeds))
    def command(values):
        probe.publish("/turtle1/cmd_vel", "geometry_msgs/Twist", {
            "linear": dict(zip("xyz", values[:3])), "angular": dict(zip("xyz", values[3:]))})
        published.append(values)
        turtlesim.assert_poses_inside()

    command()
    print("fuzzed /turtle1/cmd_vel: {} messages".format(len(published)))
    assert len(published) >= MIN_REQUESTS
    settle = probe.collect(POSE, 1.0)
    assert len(settle) > 30, "turtle1/pose stopped"
    assert all(inside(entry["msg"]) for entry in settle)
    turtlesim.watch.assert_alive()
    turtlesim.reset()
    probe.publish("/turtle1/cmd_vel", "geometry_msgs/Twist", {"linear": {"x": 2.0}})
    turtlesim.next_pose(lambda pose: pose["x"] > CENTRE + 0.5 and pose["y"] == pytest.approx(CENTRE))
