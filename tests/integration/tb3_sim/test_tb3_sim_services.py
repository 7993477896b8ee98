"""The /gazebo/* services of tb3_sim through ROS, as course code calls them (rospy.ServiceProxy, rosservice):
every service's success and failure path, reset_world vs reset_simulation, pause, /gazebo/model_states."""
import math
import subprocess

import pytest
import rospy
from gazebo_msgs.msg import ModelState
from gazebo_msgs.srv import (
    DeleteModel,
    GetModelState,
    GetPhysicsProperties,
    GetWorldProperties,
    SetModelState,
    SpawnModel,
)
from geometry_msgs.msg import Pose
from std_srvs.srv import Empty

from roslab import wait_for_service
from tb3_sim.core.model_xml import box_sdf
from tb3_sim.core.world import MAX_MODELS

SERVICES = ["reset_world", "reset_simulation", "pause_physics", "unpause_physics", "spawn_sdf_model",
            "spawn_urdf_model", "delete_model", "get_model_state", "set_model_state", "get_world_properties"]
URDF_BOX = ("<robot name='crate'><link name='l'><collision><geometry><box size='0.2 0.2 0.5'/></geometry>"
            "</collision></link></robot>")


@pytest.fixture(scope="module")
def sim(ros_master):
    process = ros_master.roslaunch("tb3_sim", "tb3_sim.launch", "world:=turtlebot3_world", "x_pos:=-2.0",
                                   "y_pos:=-0.5")
    for name in SERVICES:
        wait_for_service(ros_master.uri, "/gazebo/" + name)
    return process


@pytest.fixture(scope="module")
def probe(ros_master, sim):
    probe = ros_master.probe()
    probe.subscribe("/clock", "rosgraph_msgs/Clock")
    probe.subscribe("/gazebo/model_states", "gazebo_msgs/ModelStates")
    probe.subscribe("/odom", "nav_msgs/Odometry")
    probe.wait_for_message("/gazebo/model_states")
    return probe


def call(name, srv_type, *args, **fields):
    return rospy.ServiceProxy("/gazebo/" + name, srv_type)(*args, **fields)


def pose(x, y, yaw=0.0):
    message = Pose()
    message.position.x, message.position.y = x, y
    message.orientation.z, message.orientation.w = math.sin(yaw / 2), math.cos(yaw / 2)
    return message


def spawn(name, x, y, xml=None, service="spawn_sdf_model", frame=""):
    return call(service, SpawnModel, model_name=name, model_xml=xml or box_sdf(name, 0.3, 0.3, 0.4),
                initial_pose=pose(x, y), reference_frame=frame)


def position(name, relative=""):
    reply = call("get_model_state", GetModelState, model_name=name, relative_entity_name=relative)
    assert reply.success, reply.status_message
    return reply.pose.position.x, reply.pose.position.y


def latest_clock(probe):
    return probe.wait_for_message("/clock")["clock"]


def test_spawn_sdf_box_appears_in_model_states_and_get_model_state(probe):
    reply = spawn("box_a", -1.0, -0.5)
    assert (reply.success, reply.status_message) == (True, "SpawnModel: Successfully spawned entity")
    assert position("box_a") == pytest.approx((-1.0, -0.5), abs=1e-6)
    states = probe.wait_for_message("/gazebo/model_states", predicate=lambda m: "box_a" in m["name"])
    assert states["name"][:3] == ["ground_plane", "ros_symbol", "turtlebot3_waffle"]


def test_spawn_failures(sim):
    assert spawn("box_a", 0.55, 0.55).status_message == "SpawnModel: Failure - entity already exists."
    reply = spawn("bad", 0.55, 0.55, xml="<sdf><model")
    assert not reply.success and "not SDF or URDF" in reply.status_message
    reply = spawn("not_urdf", 0.55, 0.55, service="spawn_urdf_model")
    assert (reply.success, reply.status_message) == (False, "SpawnModel: Failure - model format is not URDF.")
    reply = spawn("on_robot", -2.0, -0.5)
    assert not reply.success and "would overlap 'turtlebot3_waffle'" in reply.status_message
    assert sim.running()


def test_spawn_urdf_and_reference_frame(sim):
    assert spawn("crate", 0.55, 0.55, xml=URDF_BOX, service="spawn_urdf_model").success
    assert spawn("next_to_crate", 0.0, 0.3, frame="crate").success
    assert position("next_to_crate") == pytest.approx((0.55, 0.85), abs=1e-6)
    assert position("next_to_crate", "crate") == pytest.approx((0.0, 0.3), abs=1e-6)


def test_delete_model(sim):
    assert spawn("doomed", 0.55, -0.55).success
    reply = call("delete_model", DeleteModel, model_name="doomed")
    assert (reply.success, reply.status_message) == (True, "DeleteModel: successfully deleted model")
    reply = call("delete_model", DeleteModel, model_name="doomed")
    assert (reply.success, reply.status_message) == (False, "DeleteModel: model does not exist")
    reply = call("delete_model", DeleteModel, model_name="turtlebot3_waffle")
    assert not reply.success and "is a robot" in reply.status_message


def test_get_model_state_failures(sim):
    reply = call("get_model_state", GetModelState, model_name="nothing", relative_entity_name="")
    assert (reply.success, reply.status_message) == (False, "GetModelState: model does not exist")
    reply = call("get_model_state", GetModelState, model_name="turtlebot3_waffle", relative_entity_name="x")
    assert not reply.success and "relative_entity_name not found" in reply.status_message


def test_set_model_state_service_and_topic(probe):
    state = ModelState(model_name="box_a", pose=pose(-1.0, 0.55), reference_frame="world")
    reply = call("set_model_state", SetModelState, model_state=state)
    assert (reply.success, reply.status_message) == (True, "SetModelState: set model state done")
    assert position("box_a") == pytest.approx((-1.0, 0.55), abs=1e-3)
    probe.publish("/gazebo/set_model_state", "gazebo_msgs/ModelState",
                  {"model_name": "box_a", "pose": {"position": {"x": -1.0, "y": 0.6}, "orientation": {"w": 1.0}}})
    probe.wait_for_message("/gazebo/model_states", predicate=lambda m: m["pose"][m["name"].index("box_a")][
        "position"]["y"] == pytest.approx(0.6, abs=1e-3))
    reply = call("set_model_state", SetModelState, model_state=ModelState(model_name="nothing", pose=pose(0, 0)))
    assert (reply.success, reply.status_message) == (False, "SetModelState: model does not exist")


def test_get_world_properties(sim):
    reply = call("get_world_properties", GetWorldProperties)
    assert reply.success and reply.status_message == "GetWorldProperties: got properties"
    assert reply.sim_time > 0
    assert reply.model_names[:3] == ["ground_plane", "ros_symbol", "turtlebot3_waffle"]
    assert {"box_a", "crate"} <= set(reply.model_names)


def test_reset_world_restores_poses_keeps_models_and_time_runs_on(probe):
    call("set_model_state", SetModelState, model_state=ModelState(model_name="turtlebot3_waffle",
                                                                 pose=pose(0.55, -0.55, 1.0)))
    before = latest_clock(probe)
    call("reset_world", Empty)
    assert position("turtlebot3_waffle") == pytest.approx((-2.0, -0.5), abs=1e-3)
    assert position("box_a") == pytest.approx((-1.0, -0.5), abs=1e-3)
    assert position("crate") == pytest.approx((0.55, 0.55), abs=1e-3)
    probe.take("/clock")
    assert latest_clock(probe) > before


def test_reset_simulation_rewinds_the_clock(probe):
    probe.wait_for_message("/clock", predicate=lambda m: m["clock"] > 1.0)
    call("reset_simulation", Empty)
    probe.take("/clock")
    assert latest_clock(probe) < 1.0
    assert "box_a" in call("get_world_properties", GetWorldProperties).model_names


def test_pause_stops_the_clock_and_unpause_resumes_it(probe):
    call("pause_physics", Empty)
    probe.collect("/clock", 0.2)
    assert probe.collect("/clock", 0.5) == []
    frozen = call("get_world_properties", GetWorldProperties).sim_time
    call("unpause_physics", Empty)
    assert probe.wait_for_message("/clock", predicate=lambda m: m["clock"] > frozen)


@pytest.mark.parametrize("max_update_rate", ["0.000000001", "0.0001"])
def test_physics_properties_that_would_stop_the_loop_are_refused(ros_master, probe, max_update_rate):
    """rosservice's call as a careless student types it: 1e-9 used to end the node with an OverflowError in its
    pacing sleep, 0.0001 to freeze /clock for a day; both are refused and the simulation runs on unchanged."""
    result = subprocess.run(["rosservice", "call", "/gazebo/set_physics_properties",
                             f"{{time_step: 0.001, max_update_rate: {max_update_rate}, gravity: {{z: -9.8}}}}"],
                            env=ros_master.env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                            timeout=30)
    assert result.returncode == 0, result.stdout
    assert "success: False" in result.stdout and "real-time factor" in result.stdout, result.stdout
    assert call("get_physics_properties", GetPhysicsProperties).max_update_rate == 200.0
    probe.take("/clock")
    ticks = [m["msg"]["clock"] for m in probe.collect("/clock", 1.0)]
    assert len(ticks) > 20 and ticks == sorted(ticks)


def test_spawning_past_the_model_limit_is_refused(sim):
    """Thousands of boxes would slow the simulator without limit: the spawn past MAX_MODELS fails with the reason,
    and the world (robots and models together) holds exactly MAX_MODELS."""
    before = set(call("get_world_properties", GetWorldProperties).model_names)
    spawned = []
    try:
        for i in range(MAX_MODELS + 1):
            reply = spawn(f"crowd_{i}", 20.0 + i % 10, 20.0 + i // 10)
            if not reply.success:
                break
            spawned.append(f"crowd_{i}")
        assert (reply.success, reply.status_message) == (
            False, f"SpawnModel: Failure - the world already holds {MAX_MODELS} models (robots included), tb3_sim's "
                   f"limit: delete a model before spawning another")
        held = set(call("get_world_properties", GetWorldProperties).model_names) - {"ground_plane", "ros_symbol"}
        assert len(held) == MAX_MODELS and set(spawned) <= held
    finally:
        for name in spawned:
            call("delete_model", DeleteModel, model_name=name)
    assert set(call("get_world_properties", GetWorldProperties).model_names) == before


def test_rosservice_call_from_the_command_line(ros_master, sim):
    result = subprocess.run(["rosservice", "call", "/gazebo/get_model_state",
                             "{model_name: turtlebot3_waffle, relative_entity_name: world}"],
                            env=ros_master.env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                            timeout=30)
    assert result.returncode == 0, result.stdout
    assert 'status_message: "GetModelState: got properties"' in result.stdout


def run_spawn_box(ros_master, *args):
    result = subprocess.run(["rosrun", "tb3_sim", "spawn_box", *args], env=ros_master.env, stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, text=True, timeout=60)
    return result.returncode, result.stdout, result.stderr


def test_spawn_box_tool(ros_master, sim):
    code, out, err = run_spawn_box(ros_master, "cli_box", "0.55", "-0.55", "--size", "0.2", "--yaw", "0.5")
    assert (code, err) == (0, "")
    assert out == ("SpawnModel: Successfully spawned entity: 'cli_box', 0.2 x 0.2 x 0.2 m, 1 kg, at (0.55, -0.55) "
                   "yaw 0.5\n")
    assert position("cli_box") == pytest.approx((0.55, -0.55), abs=1e-3)
    code, out, err = run_spawn_box(ros_master, "cli_box", "0.55", "-0.55")
    assert (code, out, err) == (1, "", "spawn_box: SpawnModel: Failure - entity already exists.\n")


@pytest.mark.parametrize("package, y", [("tb3_sim", -1.0), ("gazebo_ros", -1.5)])
def test_spawn_model_tool_from_a_file_and_a_parameter(ros_master, sim, tmp_path, package, y):
    """`rosrun gazebo_ros spawn_model ...` as course pages write it runs the same tool."""
    name = "crate_" + package
    model = tmp_path / "crate.urdf"
    model.write_text(URDF_BOX)
    result = subprocess.run(["rosrun", package, "spawn_model", "-urdf", "-file", str(model), "-model", name,
                             "-x", "0.55", "-y", str(y)], env=ros_master.env, stdout=subprocess.PIPE,
                            stderr=subprocess.STDOUT, text=True, timeout=60)
    assert result.returncode == 0, result.stdout
    assert "Spawn status: SpawnModel: Successfully spawned entity" in result.stdout
    assert position(name) == pytest.approx((0.55, y), abs=1e-3)
    subprocess.run(["rosparam", "set", "/crate_description", URDF_BOX], env=ros_master.env, check=True, timeout=30)
    result = subprocess.run(["rosrun", package, "spawn_model", "-urdf", "-param", "crate_description", "-model",
                             name], env=ros_master.env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                            text=True, timeout=60)
    assert result.returncode == 1
    assert "Spawn status: SpawnModel: Failure - entity already exists.\nSpawn service failed. Exiting." in \
        result.stdout
