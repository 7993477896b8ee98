"""Fuzzing tb3_sim (issue 8, item 1): every /gazebo/* service with generated requests, and /cmd_vel.

One simulator (approach arena, real_time_factor 2) serves the whole module. Each test sends at least
MIN_REQUESTS generated requests to a service (NaN, +-inf, huge and tiny numbers, malformed and hostile XML,
unknown and unicode names) and checks every reply against the service's documented behaviour (see
tb3_sim.ros.gazebo_api): success True only for a request that can be carried out, otherwise success False with a
status_message; never an unhandled exception, never a hang. Afterwards the node is the same process, still
offers every service, printed no traceback, and answers a valid request correctly. /cmd_vel gets fuzzed
Twists while the robot's /odom pose must stay finite and inside the arena.
"""
import math
import time
from collections import Counter

import pytest
import rospy
from gazebo_msgs.msg import ModelState
from gazebo_msgs.srv import DeleteModel, GetModelState, GetWorldProperties, SetModelState, SpawnModel
from geometry_msgs.msg import Pose, Twist
from hypothesis import given, settings
from hypothesis import strategies as st
from std_srvs.srv import Empty

from roslab import wait_for_service
from roslab.fuzz import FUZZ_SETTINGS, MIN_REQUESTS, GraphWatch, ServiceFuzzer
from roslab.fuzz_strategies import float64s, graph_names, model_xml_garbage, model_xml_models, texts
from roslab.robot_view import pose_of

ROBOT = "turtlebot3_waffle"
WORLD_MODELS = ["target_box", "side_box", "post"]
FIXED_MODELS = ["ground_plane", "approach_arena"]
WORLD_FRAMES = ["", "world", "map", "/map"]
ARENA_X_M, ARENA_Y_M = (-1.0, 3.0), (-1.5, 1.5)   # inner faces of the arena's walls
FREE_SPOT = (2.5, 1.1)                              # an empty corner of the arena
EMPTY_SERVICES = ["reset_world", "reset_simulation", "pause_physics", "unpause_physics"]
SERVICES = ["/gazebo/" + name for name in EMPTY_SERVICES + [
    "snapshot", "spawn_sdf_model", "spawn_urdf_model", "delete_model", "get_model_state", "set_model_state",
    "get_world_properties"]]
BOX_SDF = ("<sdf version='1.6'><model name='known'><link name='l'><collision name='c'><geometry><box>"
           "<size>0.2 0.2 0.2</size></box></geometry></collision></link></model></sdf>")
BOX_URDF = ("<robot name='known'><link name='l'><collision><geometry><box size='0.2 0.2 0.2'/></geometry>"
            "</collision></link></robot>")
KNOWN_XML = {"spawn_sdf_model": BOX_SDF, "spawn_urdf_model": BOX_URDF}


class Sim:
    """The module's simulator: its launch process, a probe subscribed to /odom, and the GraphWatch."""

    def __init__(self, ros_master):
        self.process = ros_master.roslaunch("tb3_sim", "tb3_sim.launch", "world:=approach_arena", "gui:=false",
                                            "real_time_factor:=2",
                                            "snapshot_path:={}".format(ros_master.workdir / "tb3_sim.png"))
        for name in SERVICES:
            wait_for_service(ros_master.uri, name, timeout_s=60)
        self.probe = ros_master.probe()
        self.probe.subscribe("/odom", "nav_msgs/Odometry")
        self.watch = GraphWatch(ros_master.uri, ["/gazebo"], SERVICES, [self.process])

    def call(self, name, service_class, *args, **fields):
        return rospy.ServiceProxy("/gazebo/" + name, service_class)(*args, **fields)

    def model_names(self):
        return set(self.call("get_world_properties", GetWorldProperties).model_names)

    def restore(self):
        """Running, with every model and the robot at its initial pose, and only the world's own models."""
        self.call("unpause_physics", Empty)
        for name in self.model_names() - set(WORLD_MODELS + FIXED_MODELS + [ROBOT]):
            assert self.call("delete_model", DeleteModel, name).success
        self.call("reset_world", Empty)

    def assert_still_serving(self):
        """Same process, every service registered, no traceback, and /odom still flowing in sim time."""
        self.watch.assert_alive()
        self.probe.take("/odom")
        first = self.probe.wait_for_message("/odom", timeout_s=5)["header"]["stamp"]
        later = self.probe.wait_for_message("/odom", timeout_s=5,
                                            predicate=lambda odom: odom["header"]["stamp"] > first)
        assert all(math.isfinite(value) for value in pose_of(later))


@pytest.fixture(scope="module")
def sim(ros_master):
    sim = Sim(ros_master)
    yield sim
    sim.assert_still_serving()


@pytest.fixture
def clean(sim):
    sim.restore()
    yield sim
    sim.restore()


def pose_message(x, y, quaternion=(0.0, 0.0, 0.0, 1.0), z=0.0):
    message = Pose()
    message.position.x, message.position.y, message.position.z = x, y, z
    (message.orientation.x, message.orientation.y, message.orientation.z,
     message.orientation.w) = quaternion
    return message


def twist_message(values):
    message = Twist()
    (message.linear.x, message.linear.y, message.linear.z,
     message.angular.x, message.angular.y, message.angular.z) = values
    return message


def poses():
    """Any Pose (NaN, inf, huge, unnormalised quaternions), or a sensible one somewhere in the arena."""
    anything = st.builds(pose_message, float64s(), float64s(), st.tuples(*[float64s()] * 4), float64s())
    sensible = st.builds(pose_message, st.floats(*ARENA_X_M), st.floats(*ARENA_Y_M),
                         st.sampled_from([(0.0, 0.0, 0.0, 1.0), (0.0, 0.0, 0.0, 0.0), (0.0, 0.0, 1.0, 1.0)]))
    return st.one_of(anything, sensible)


def finite_pose(message):
    position, q = message.position, message.orientation
    return all(math.isfinite(v) for v in (position.x, position.y, q.x, q.y, q.z, q.w))


def model_names():
    return st.one_of(st.sampled_from([ROBOT, "fuzz_box"] + WORLD_MODELS + FIXED_MODELS), graph_names())


def frame_names():
    return st.one_of(st.sampled_from(WORLD_FRAMES + [ROBOT, "target_box", "target_box::link", "nothing"]),
                     texts())


def frame_exists(name, existing):
    return name in WORLD_FRAMES or name.split("::", 1)[0] in existing


def spawn_fuzzer(sim, service):
    """A ServiceFuzzer for `service` and the check of one spawn reply: a failure with a message, or a model
    that really exists at a finite pose (deleted again, so that every request meets the same world)."""
    fuzzer = ServiceFuzzer("/gazebo/" + service, SpawnModel)

    def spawn(name, xml, pose, frame):
        reply = fuzzer.call(model_name=name, model_xml=xml, robot_namespace="", initial_pose=pose,
                            reference_frame=frame)
        assert reply.error is None, reply.error
        if not reply.response.success:
            assert "SpawnModel" in reply.response.status_message
            return
        assert finite_pose(pose), "spawned at a non-finite pose"
        spawned = sorted(sim.model_names() - set(WORLD_MODELS + FIXED_MODELS + [ROBOT]))
        assert len(spawned) == 1, spawned
        state = sim.call("get_model_state", GetModelState, spawned[0], "")
        assert state.success and finite_pose(state.pose)
        assert sim.call("delete_model", DeleteModel, spawned[0]).success
    return fuzzer, spawn


def assert_spawns_a_known_box(sim, service):
    reply = sim.call(service, SpawnModel, "known", KNOWN_XML[service], "", pose_message(*FREE_SPOT), "")
    assert (reply.success, reply.status_message) == (True, "SpawnModel: Successfully spawned entity")
    state = sim.call("get_model_state", GetModelState, "known", "")
    assert (state.pose.position.x, state.pose.position.y) == pytest.approx(FREE_SPOT, abs=1e-3)


@pytest.mark.parametrize("service", ["spawn_sdf_model", "spawn_urdf_model"])
def test_spawn_models_with_fuzzed_sizes(clean, service):
    """Well-formed models with any size (zero, negative, NaN, a micrometre, a light-second) at any pose."""
    fuzzer, spawn = spawn_fuzzer(clean, service)
    FUZZ_SETTINGS(given(name=st.just(""), xml=model_xml_models(), pose=poses(), frame=st.just(""))(spawn))()
    print("fuzzed /gazebo/{} with models: {} requests".format(service, fuzzer.calls))
    assert fuzzer.calls >= MIN_REQUESTS
    clean.assert_still_serving()
    assert_spawns_a_known_box(clean, service)


@pytest.mark.parametrize("service", ["spawn_sdf_model", "spawn_urdf_model"])
def test_spawn_garbage(clean, service):
    """Malformed, truncated, random and hostile XML, with any name, pose and reference frame."""
    fuzzer, spawn = spawn_fuzzer(clean, service)
    FUZZ_SETTINGS(given(name=st.one_of(st.just(""), model_names()), xml=model_xml_garbage(), pose=poses(),
                        frame=frame_names())(spawn))()
    print("fuzzed /gazebo/{} with garbage: {} requests".format(service, fuzzer.calls))
    assert fuzzer.calls >= MIN_REQUESTS
    clean.assert_still_serving()
    assert_spawns_a_known_box(clean, service)


def test_delete_fuzzed_names(clean):
    """Only a model that exists and is neither the robot nor fixed world geometry can be deleted."""
    fuzzer = ServiceFuzzer("/gazebo/delete_model", DeleteModel)

    @FUZZ_SETTINGS
    @given(name=st.one_of(st.sampled_from(["fuzz_box", ROBOT] + FIXED_MODELS), graph_names()))
    def delete(name):
        existing = clean.model_names()
        if "fuzz_box" not in existing:
            assert clean.call("spawn_sdf_model", SpawnModel, "fuzz_box", BOX_SDF, "",
                              pose_message(*FREE_SPOT), "").success
            existing.add("fuzz_box")
        reply = fuzzer.call(name)
        assert reply.error is None, reply.error
        deletable = name in existing and name not in FIXED_MODELS + [ROBOT]
        assert reply.response.success is deletable, (name, reply.response.status_message)
        assert reply.response.status_message.startswith("DeleteModel")

    delete()
    print("fuzzed /gazebo/delete_model: {} requests".format(fuzzer.calls))
    assert fuzzer.calls >= MIN_REQUESTS
    clean.assert_still_serving()
    assert clean.call("delete_model", DeleteModel, ROBOT).success is False
    assert ROBOT in clean.model_names()


def test_get_model_state_fuzzed_names_and_frames(clean):
    """Success exactly when the model and the frame exist; then a finite pose."""
    fuzzer = ServiceFuzzer("/gazebo/get_model_state", GetModelState)
    existing = clean.model_names()

    @FUZZ_SETTINGS
    @given(name=model_names(), relative=frame_names())
    def get(name, relative):
        reply = fuzzer.call(name, relative)
        assert reply.error is None, reply.error
        expected = name in existing and frame_exists(relative, existing)
        assert reply.response.success is expected, (name, relative, reply.response.status_message)
        if expected:
            assert finite_pose(reply.response.pose)

    get()
    print("fuzzed /gazebo/get_model_state: {} requests".format(fuzzer.calls))
    assert fuzzer.calls >= MIN_REQUESTS
    clean.assert_still_serving()
    clean.probe.take("/odom")
    odom = pose_of(clean.probe.wait_for_message("/odom"))
    state = clean.call("get_model_state", GetModelState, ROBOT, "world")
    assert (state.pose.position.x, state.pose.position.y) == pytest.approx(odom[:2], abs=1e-3)


def test_set_model_state_fuzzed_poses_and_twists(clean):
    """Non-finite values, unknown models or frames and fixed geometry are refused; a sensible request in the
    world frame succeeds; the simulation keeps stepping with finite poses whatever was accepted."""
    fuzzer = ServiceFuzzer("/gazebo/set_model_state", SetModelState)
    existing = clean.model_names()

    @FUZZ_SETTINGS
    @given(name=model_names(), pose=poses(), twist=st.tuples(*[float64s()] * 6), frame=frame_names())
    def set_state(name, pose, twist, frame):
        state = ModelState(model_name=name, pose=pose, twist=twist_message(twist), reference_frame=frame)
        reply = fuzzer.call(state)
        assert reply.error is None, reply.error
        response = reply.response
        finite = finite_pose(pose) and all(math.isfinite(v) for v in (twist[0], twist[1], twist[5]))
        movable = name in existing and name not in FIXED_MODELS
        if not (finite and movable and frame_exists(frame, existing)):
            assert response.success is False, (name, frame, response.status_message)
        elif frame in WORLD_FRAMES and sensible(pose, twist):
            assert response.success is True, (name, response.status_message)
        if response.success:
            moved = clean.call("get_model_state", GetModelState, name, "")
            assert moved.success and finite_pose(moved.pose)

    set_state()
    print("fuzzed /gazebo/set_model_state: {} requests".format(fuzzer.calls))
    assert fuzzer.calls >= MIN_REQUESTS
    clean.assert_still_serving()
    clean.call("reset_world", Empty)
    target = ModelState(model_name="target_box", pose=pose_message(*FREE_SPOT), reference_frame="world")
    assert clean.call("set_model_state", SetModelState, target).success
    state = clean.call("get_model_state", GetModelState, "target_box", "")
    assert (state.pose.position.x, state.pose.position.y) == pytest.approx(FREE_SPOT, abs=1e-3)


def sensible(pose, twist):
    """Inside the arena, a normalisable quaternion, and a speed a real object could have."""
    q = pose.orientation
    return (ARENA_X_M[0] <= pose.position.x <= ARENA_X_M[1] and ARENA_Y_M[0] <= pose.position.y <= ARENA_Y_M[1]
            and abs(pose.position.z) < 10 and 1e-3 < math.sqrt(q.x ** 2 + q.y ** 2 + q.z ** 2 + q.w ** 2) < 1e3
            and all(abs(v) <= 10.0 for v in (twist[0], twist[1], twist[5])))


def test_world_control_sequences(clean):
    """Any order of reset_world, reset_simulation, pause, unpause and get_world_properties: each call answers,
    and afterwards pause stops sim time and unpause starts it again. (~snapshot, a PNG render of a quarter
    second, is left to the tb3_sim tests.) Sequences of up to 4 calls (780 of them) give each service its
    MIN_REQUESTS in about 1450 calls; up to 8 took 2293, 12 ms each."""
    fuzzers = {name: ServiceFuzzer("/gazebo/" + name, Empty) for name in EMPTY_SERVICES}
    properties = ServiceFuzzer("/gazebo/get_world_properties", GetWorldProperties)
    operations = EMPTY_SERVICES + ["get_world_properties"]

    @settings(FUZZ_SETTINGS, max_examples=2 * MIN_REQUESTS)
    @given(sequence=st.lists(st.sampled_from(operations), min_size=1, max_size=4))
    def control(sequence):
        for name in sequence:
            reply = (properties if name == "get_world_properties" else fuzzers[name]).call()
            assert reply.error is None, (name, reply.error)
            if name == "get_world_properties":
                assert reply.response.success and ROBOT in reply.response.model_names
                assert math.isfinite(reply.response.sim_time) and reply.response.sim_time >= 0

    control()
    counts = Counter({name: fuzzer.calls for name, fuzzer in fuzzers.items()}, get_world_properties=properties.calls)
    print("fuzzed /gazebo world control: {}".format(dict(counts)))
    assert min(counts.values()) >= MIN_REQUESTS, counts
    clean.call("pause_physics", Empty)
    paused_at = clean.call("get_world_properties", GetWorldProperties).sim_time
    time.sleep(0.3)
    assert clean.call("get_world_properties", GetWorldProperties).sim_time == paused_at
    clean.call("unpause_physics", Empty)
    time.sleep(0.3)
    assert clean.call("get_world_properties", GetWorldProperties).sim_time > paused_at
    clean.assert_still_serving()


def inside_arena(odom):
    x, y, yaw = pose_of(odom)
    return (all(math.isfinite(v) for v in (x, y, yaw))
            and ARENA_X_M[0] < x < ARENA_X_M[1] and ARENA_Y_M[0] < y < ARENA_Y_M[1])


def test_cmd_vel_fuzzed_twists_keep_the_robot_finite_and_inside(clean):
    """Every field of /cmd_vel fuzzed, sane commands up to the 10 m/s limit included (the robot slams into
    the walls): /odom keeps coming with finite poses inside the arena's walls."""
    probe = clean.probe
    published = []
    speeds = st.one_of(float64s(), st.floats(-10.0, 10.0), st.floats(-30.0, 30.0))

    @FUZZ_SETTINGS
    @given(values=st.tuples(speeds, float64s(), float64s(), float64s(), float64s(), speeds))
    def command(values):
        probe.publish("/cmd_vel", "geometry_msgs/Twist", {
            "linear": dict(zip("xyz", values[:3])), "angular": dict(zip("xyz", values[3:]))})
        published.append(values)
        for entry in probe.take("/odom"):
            assert inside_arena(entry["msg"]), (values, pose_of(entry["msg"]))

    probe.take("/odom")
    command()
    print("fuzzed /cmd_vel: {} messages".format(len(published)))
    assert len(published) >= MIN_REQUESTS
    settle = probe.collect("/odom", 1.0)
    assert len(settle) > 10, "/odom stopped"
    assert all(inside_arena(entry["msg"]) for entry in settle)
    clean.assert_still_serving()
    probe.publish("/cmd_vel", "geometry_msgs/Twist", {})
    time.sleep(0.5)
    clean.call("reset_world", Empty)
    probe.wait_for_message("/odom", timeout_s=10, predicate=lambda odom: max(map(abs, pose_of(odom))) < 1e-3)
    probe.publish("/cmd_vel", "geometry_msgs/Twist", {"linear": {"x": 0.2}})
    moved = probe.wait_for_message("/odom", timeout_s=10, predicate=lambda odom: pose_of(odom)[0] > 0.1)
    probe.publish("/cmd_vel", "geometry_msgs/Twist", {})
    assert abs(pose_of(moved)[1]) < 0.01
