"""The /gazebo/* service handlers over a real World (no master): Gazebo's semantics and status strings."""
import math

import pytest
from gazebo_msgs.msg import ModelState
from gazebo_msgs.srv import (
    DeleteModelRequest,
    GetModelStateRequest,
    GetWorldPropertiesRequest,
    SetModelStateRequest,
    SpawnModelRequest,
)
from geometry_msgs.msg import Pose, Quaternion
from std_srvs.srv import EmptyRequest

from tb3_sim.core.errors import ProtectedModelError
from tb3_sim.core.geometry import Pose2D, yaw_to_quaternion
from tb3_sim.core.model_xml import box_sdf
from tb3_sim.core.world import World
from tb3_sim.core.world_file import load_world, shipped_world_path
from tb3_sim.ros.gazebo_api import GazeboApi, failure_message


@pytest.fixture
def sim(fake_sim):
    return fake_sim(World(load_world(shipped_world_path("turtlebot3_world")), Pose2D(-2.0, -0.5, 0.0)))


@pytest.fixture
def api(sim):
    return GazeboApi(sim)


def _pose(x, y, yaw):
    message = Pose()
    message.position.x, message.position.y = x, y
    message.orientation = Quaternion(*yaw_to_quaternion(yaw))
    return message


def spawn(api, name, x, y, yaw=0.0, xml=None, frame="", urdf=False):
    request = SpawnModelRequest(model_name=name, model_xml=xml or box_sdf("xml_name", 0.2, 0.2, 0.3),
                                initial_pose=_pose(x, y, yaw), reference_frame=frame)
    return (api.spawn_urdf_model if urdf else api.spawn_sdf_model)(request)


def state(api, name, relative=""):
    return api.get_model_state(GetModelStateRequest(model_name=name, relative_entity_name=relative))


def test_spawn_then_get_state(api):
    reply = spawn(api, "box1", -1.0, -0.5, yaw=0.3)
    assert (reply.success, reply.status_message) == (True, "SpawnModel: Successfully spawned entity")
    got = state(api, "box1")
    assert got.success and got.status_message == "GetModelState: got properties"
    assert (got.pose.position.x, got.pose.position.y) == pytest.approx((-1.0, -0.5))
    assert 2 * math.atan2(got.pose.orientation.z, got.pose.orientation.w) == pytest.approx(0.3)


def test_model_name_empty_uses_the_xml_name(api, sim):
    assert spawn(api, "", -1.0, -0.5).success
    assert sim.world.has_model("xml_name")


def test_name_clash_is_gazebos_message(api):
    assert spawn(api, "box1", -1.0, -0.5).success
    reply = spawn(api, "box1", -1.0, 1.5)
    assert (reply.success, reply.status_message) == (False, "SpawnModel: Failure - entity already exists.")


def test_robot_name_clash_too(api):
    assert spawn(api, "turtlebot3_waffle", -1.0, 1.5).status_message == "SpawnModel: Failure - entity already exists."


def test_overlap_with_the_robot_is_refused(api):
    reply = spawn(api, "box1", -1.9, -0.5)
    assert not reply.success
    assert reply.status_message.startswith("SpawnModel: Failure - model 'box1' would overlap 'turtlebot3_waffle'")


def test_unparsable_xml(api):
    reply = spawn(api, "box1", 0.5, 0.5, xml="<sdf><model")
    assert not reply.success
    assert reply.status_message.startswith("GazeboRosApiPlugin SpawnModel Failure: input model_xml not SDF or URDF")
    assert "XML syntax error" in reply.status_message


def test_unsupported_geometry(api):
    xml = ("<sdf><model name='m'><link name='l'><collision name='c'><geometry><mesh><uri>a.dae</uri></mesh>"
           "</geometry></collision></link></model></sdf>")
    reply = spawn(api, "mesh", -1.0, -0.5, xml=xml)
    assert (reply.success, reply.status_message) == (
        False, "SpawnModel: Failure - unsupported geometry <mesh>; use <box>, <cylinder> or <sphere>")


def test_urdf_service_refuses_sdf_and_accepts_urdf(api):
    reply = spawn(api, "box1", -1.0, -0.5, urdf=True)
    assert (reply.success, reply.status_message) == (False, "SpawnModel: Failure - model format is not URDF.")
    urdf = ("<robot name='r'><link name='l'><collision><geometry><cylinder radius='0.1' length='0.3'/>"
            "</geometry></collision></link></robot>")
    assert spawn(api, "can", -1.0, -0.5, xml=urdf, urdf=True).success


def test_reference_frame_composes_with_a_model(api):
    assert spawn(api, "anchor", -1.0, -1.6, yaw=math.pi / 2).success
    assert spawn(api, "child", 1.0, 0.0, frame="anchor").success
    got = state(api, "child")
    assert (got.pose.position.x, got.pose.position.y) == pytest.approx((-1.0, -0.6))
    assert spawn(api, "scoped", 0.5, 0.5, frame="anchor::link").success


def test_unknown_reference_frame(api):
    reply = spawn(api, "box1", 0.5, 0.5, frame="nowhere")
    assert reply.status_message == ("SpawnModel: reference reference_frame not found, did you forget to scope "
                                    "the link by model name?")


def test_nan_initial_pose_is_refused(api):
    reply = spawn(api, "box1", float("nan"), 0.5)
    assert (reply.success, reply.status_message) == (
        False, "SpawnModel: Failure - initial_pose must hold finite numbers")


def test_delete(api, sim):
    assert spawn(api, "box1", -1.0, -0.5).success
    reply = api.delete_model(DeleteModelRequest("box1"))
    assert (reply.success, reply.status_message) == (True, "DeleteModel: successfully deleted model")
    assert not sim.world.has_model("box1")
    reply = api.delete_model(DeleteModelRequest("box1"))
    assert (reply.success, reply.status_message) == (False, "DeleteModel: model does not exist")


@pytest.mark.parametrize("name, reason", [("turtlebot3_waffle", "is a robot"), ("ros_symbol", "fixed world"),
                                          ("ground_plane", "fixed world")])
def test_delete_refuses_the_robot_and_world_geometry(api, name, reason):
    reply = api.delete_model(DeleteModelRequest(name))
    assert not reply.success
    assert reply.status_message.startswith("DeleteModel: Failure - ") and reason in reply.status_message


def test_get_model_state_header_counts_calls_per_model(api):
    first, second = state(api, "turtlebot3_waffle", "world"), state(api, "turtlebot3_waffle", "map")
    assert (first.header.seq, second.header.seq) == (1, 2)
    assert (first.header.frame_id, second.header.frame_id) == ("world", "map")
    assert state(api, "ground_plane").header.seq == 1


@pytest.mark.parametrize("relative", ["", "world", "map", "/map"])
def test_get_model_state_world_frames(api, relative):
    got = state(api, "turtlebot3_waffle", relative)
    assert got.success and (got.pose.position.x, got.pose.position.y) == pytest.approx((-2.0, -0.5))


def test_get_model_state_failures(api):
    assert state(api, "nothing").status_message == "GetModelState: model does not exist"
    reply = state(api, "turtlebot3_waffle", "nothing")
    assert (reply.success, reply.status_message) == (False, "GetModelState: reference relative_entity_name not "
                                                            "found, did you forget to scope the body by model name?")


def test_get_model_state_relative_to_a_model(api):
    assert spawn(api, "box1", -1.0, -0.5, yaw=math.pi / 2).success
    got = state(api, "turtlebot3_waffle", "box1")
    assert (got.pose.position.x, got.pose.position.y) == pytest.approx((0.0, 1.0), abs=1e-6)


def test_get_model_state_twist_is_in_the_world_frame(api, sim):
    sim.world.set_model_state("turtlebot3_waffle", Pose2D(-2.0, -0.5, math.pi / 2))
    sim.world.robot.set_command(0.2, 0.0)
    sim.world.run(1.0)
    got = state(api, "turtlebot3_waffle")
    assert (got.twist.linear.x, got.twist.linear.y) == pytest.approx((0.0, 0.2), abs=1e-3)


def set_state(api, name, x, y, yaw=0.0, vx=0.0, frame=""):
    message = ModelState(model_name=name, pose=_pose(x, y, yaw), reference_frame=frame)
    message.twist.linear.x = vx
    return api.set_model_state(SetModelStateRequest(message))


def test_set_model_state_teleports(api, sim):
    reply = set_state(api, "turtlebot3_waffle", 0.55, 0.55, yaw=1.0)
    assert (reply.success, reply.status_message) == (True, "SetModelState: set model state done")
    assert sim.world.robot.pose == pytest.approx(Pose2D(0.55, 0.55, 1.0))
    assert sim.teleports == 1


def test_set_model_state_in_a_reference_frame(api, sim):
    assert spawn(api, "box1", -1.0, -0.5, yaw=math.pi / 2).success
    assert set_state(api, "turtlebot3_waffle", 0.5, 0.0, frame="box1").success
    assert sim.world.robot.pose == pytest.approx(Pose2D(-1.0, 0.0, math.pi / 2))


def test_set_model_state_normalises_a_zero_quaternion(api, sim):
    message = ModelState(model_name="turtlebot3_waffle", pose=Pose())
    message.pose.position.x = 0.55
    assert api.set_model_state(SetModelStateRequest(message)).success
    assert sim.world.robot.pose.yaw == 0.0


def test_set_model_state_failures(api):
    assert set_state(api, "nothing", 0, 0).status_message == "SetModelState: model does not exist"
    assert set_state(api, "turtlebot3_waffle", 0, 0, frame="x").status_message == (
        "SetModelState: specified reference frame entity does not exist")
    assert set_state(api, "turtlebot3_waffle", float("inf"), 0).status_message == (
        "SetModelState: Failure - pose must hold finite numbers")
    assert set_state(api, "turtlebot3_waffle", 0.5, 0.5, vx=float("nan")).status_message == (
        "SetModelState: Failure - twist must hold finite numbers")
    assert not set_state(api, "ros_symbol", 0, 0).success


def test_world_properties(api, sim):
    assert spawn(api, "box1", -1.0, -0.5).success
    sim.world.run(0.5)
    reply = api.get_world_properties(GetWorldPropertiesRequest())
    assert reply.success and reply.status_message == "GetWorldProperties: got properties"
    assert reply.sim_time == pytest.approx(0.5)
    assert reply.model_names == ["ground_plane", "ros_symbol", "turtlebot3_waffle", "box1"]
    assert reply.rendering_enabled is False


def test_pause_reset_and_unpause_reach_the_node(api, sim):
    api.pause_physics(EmptyRequest())
    assert sim.paused
    api.unpause_physics(EmptyRequest())
    assert not sim.paused
    sim.world.run(1.0)
    api.reset_simulation(EmptyRequest())
    assert sim.world.time_s == 0.0


def test_failure_message_falls_back_to_the_reason():
    assert failure_message("DeleteModel", ProtectedModelError("no")) == "DeleteModel: Failure - no"


def test_positions_beyond_a_kilometre_are_refused(api):
    reply = spawn(api, "far", 1e300, 0.0)
    assert (reply.success, reply.status_message) == (
        False, "SpawnModel: Failure - initial_pose puts the model at (1e+300, 0); tb3_sim accepts positions within "
               "±1000 m of the origin")
    assert not set_state(api, "turtlebot3_waffle", 0.0, -2000.0).success


def test_a_quaternion_that_overflows_is_refused(api):
    message = ModelState(model_name="turtlebot3_waffle", pose=Pose())
    message.pose.orientation.x, message.pose.orientation.y = 1e300, -1e300
    message.pose.orientation.z, message.pose.orientation.w = 1e300, 1e300
    reply = api.set_model_state(SetModelStateRequest(message))
    assert (reply.success, reply.status_message) == (False, "SetModelState: Failure - pose does not give a finite pose")


def test_absurd_twists_are_refused(api):
    reply = set_state(api, "turtlebot3_waffle", 0.5, 0.5, vx=1e6)
    assert (reply.success, reply.status_message) == (
        False, "SetModelState: Failure - twist is beyond the sanity limits of ±100 m/s and ±100 rad/s")
