"""The /gazebo/* services of gazebo_ros_api_plugin (noetic) over the tb3_sim core, with Gazebo's strings.

- reset_world (std_srvs/Empty): models and robot back to their initial poses, command zeroed, spawned models
  kept, sim time runs on;
- reset_simulation (std_srvs/Empty): the same, and sim time back to 0 (/clock jumps back);
- pause_physics / unpause_physics (std_srvs/Empty): stop / resume stepping, so /clock stops too;
- spawn_sdf_model (gazebo_msgs/SpawnModel): SDF or URDF (see model_xml) -> a box or cylinder model, or a
  TurtleBot3 robot with all its sensors in the request's robot_namespace (see node: spawn_robot);
- spawn_urdf_model (gazebo_msgs/SpawnModel): the same, URDF only;
- delete_model (gazebo_msgs/DeleteModel): any model but the robot, the ground plane and the world geometry;
- get_model_state (gazebo_msgs/GetModelState): world pose and world-frame twist, or relative to
  relative_entity_name; header.seq counts the calls per model, as Gazebo's does;
- set_model_state (gazebo_msgs/SetModelState, and the topic of gazebo_msgs/ModelState): teleport with a twist,
  both given in reference_frame;
- get_world_properties (gazebo_msgs/GetWorldProperties): sim_time, model_names (model_states order),
  rendering_enabled;
- get_physics_properties / set_physics_properties (gazebo_msgs/GetPhysicsProperties, SetPhysicsProperties):
  Gazebo's real-time factor is max_update_rate x time_step (max_update_rate 0: as fast as possible), and that
  product is what set_physics_properties changes here (the node's pacing, as ~real_time_factor). The physics
  step itself stays PHYSICS_STEP_S; the time_step and max_update_rate last set are reported back as given, and
  so are gravity and the ODE settings, which a 2D simulator has no use for. Before any set, time_step is the
  physics step and max_update_rate = real_time_factor / time_step.

Spawn: `model_name` overrides the XML's name (the XML's name is used when it is empty); `initial_pose` (x, y,
yaw; z, roll and pitch ignored) is composed with the pose in the XML, then with `reference_frame` (see
reference_frames). A model overlapping the robot or another model is refused, and so are positions beyond
MAX_COORDINATE_M and set_model_state speeds beyond MAX_SPEED_MPS / MAX_YAW_RATE_RADPS (Box2D is float32).
Everything answers at once (Gazebo waits up to 10 s for a spawn or 60 s for a delete to take effect; here they
take effect in the call).
All failures come back as success False and a status_message; `failure_message` is the one place that turns
core errors into Gazebo's strings.
"""

import math
from dataclasses import replace

import rospy
from gazebo_msgs.msg import ModelState, ODEPhysics
from gazebo_msgs.srv import (
    DeleteModel,
    DeleteModelResponse,
    GetModelState,
    GetModelStateResponse,
    GetPhysicsProperties,
    GetPhysicsPropertiesResponse,
    GetWorldProperties,
    GetWorldPropertiesResponse,
    SetModelState,
    SetModelStateRequest,
    SetModelStateResponse,
    SetPhysicsProperties,
    SetPhysicsPropertiesResponse,
    SpawnModel,
    SpawnModelResponse,
)
from geometry_msgs.msg import Vector3
from std_srvs.srv import Empty, EmptyResponse

from tb3_sim.core.errors import (
    BadRequestError,
    DuplicateModelError,
    ModelXmlError,
    NotModelXmlError,
    NotUrdfError,
    SimError,
    UnknownFrameError,
    UnknownModelError,
)
from tb3_sim.core.geometry import Twist2D
from tb3_sim.core.model_xml import TurtleBot3Spec, compose, parse_model_xml
from tb3_sim.core.physics_properties import physics_properties
from tb3_sim.core.reference_frames import frame_state, from_world, to_world
from tb3_sim.ros import messages

SPAWNED = "SpawnModel: Successfully spawned entity"
DELETED = "DeleteModel: successfully deleted model"
GOT_MODEL_STATE = "GetModelState: got properties"
SET_MODEL_STATE = "SetModelState: set model state done"
GOT_WORLD_PROPERTIES = "GetWorldProperties: got properties"
GOT_PHYSICS_PROPERTIES = "GetPhysicsProperties: got properties"
SET_PHYSICS_PROPERTIES = "physics engine updated"
NOT_MODEL_XML = ("GazeboRosApiPlugin SpawnModel Failure: input model_xml not SDF or URDF, or cannot be "
                 "converted to Gazebo compatible format.")

# The ODE settings of every turtlebot3_gazebo world (quick solver, 150 iterations, SOR 1.4, cfm 1e-5, erp 0.2,
# contact surface layer 0.01 m), reported until someone sets others.
TURTLEBOT3_WORLD_ODE = dict(auto_disable_bodies=False, sor_pgs_precon_iters=0, sor_pgs_iters=150, sor_pgs_w=1.4,
                            sor_pgs_rms_error_tol=0.0, contact_surface_layer=0.01, contact_max_correcting_vel=100.0,
                            cfm=1e-5, erp=0.2, max_contacts=20)

# Sanity limits of requests (Box2D works in float32): positions within 1 km, speeds as in set_model_state.
MAX_COORDINATE_M = 1000.0
MAX_SPEED_MPS = 100.0
MAX_YAW_RATE_RADPS = 100.0

# Gazebo's exact status messages for the failures it knows; other failures read "<Service>: Failure - <why>".
GAZEBO_FAILURES = {
    ("SpawnModel", DuplicateModelError): "SpawnModel: Failure - entity already exists.",
    ("SpawnModel", NotUrdfError): "SpawnModel: Failure - model format is not URDF.",
    ("SpawnModel", UnknownFrameError):
        "SpawnModel: reference reference_frame not found, did you forget to scope the link by model name?",
    ("DeleteModel", UnknownModelError): "DeleteModel: model does not exist",
    ("GetModelState", UnknownModelError): "GetModelState: model does not exist",
    ("GetModelState", UnknownFrameError):
        "GetModelState: reference relative_entity_name not found, did you forget to scope the body by model name?",
    ("SetModelState", UnknownModelError): "SetModelState: model does not exist",
    ("SetModelState", UnknownFrameError): "SetModelState: specified reference frame entity does not exist",
}


def failure_message(service, error):
    """The status_message for `error` (a SimError) raised while serving `service` (e.g. "SpawnModel")."""
    exact = GAZEBO_FAILURES.get((service, type(error)))
    if exact is not None:
        return exact
    if isinstance(error, NotModelXmlError):
        return f"{NOT_MODEL_XML} ({error})"
    return f"{service}: Failure - {error}"


class GazeboApi:
    """Service handlers over `sim` (a tb3_sim.ros.node.SimNode: locked_world(), pause(), reset_world(), ...).

    Each handler takes a request and returns a response; `advertise()` registers them under the node's
    private namespace (/gazebo/...).
    """

    def __init__(self, sim):
        self._sim = sim
        self._get_model_state_calls = {}
        self._ode_config = ODEPhysics(**TURTLEBOT3_WORLD_ODE)

    def advertise(self):
        """Register every service and the /gazebo/set_model_state topic; returns the rospy objects."""
        return [
            rospy.Service("~reset_world", Empty, self.reset_world),
            rospy.Service("~reset_simulation", Empty, self.reset_simulation),
            rospy.Service("~pause_physics", Empty, self.pause_physics),
            rospy.Service("~unpause_physics", Empty, self.unpause_physics),
            rospy.Service("~spawn_sdf_model", SpawnModel, self.spawn_sdf_model),
            rospy.Service("~spawn_urdf_model", SpawnModel, self.spawn_urdf_model),
            rospy.Service("~delete_model", DeleteModel, self.delete_model),
            rospy.Service("~get_model_state", GetModelState, self.get_model_state),
            rospy.Service("~set_model_state", SetModelState, self.set_model_state),
            rospy.Service("~get_world_properties", GetWorldProperties, self.get_world_properties),
            rospy.Service("~get_physics_properties", GetPhysicsProperties, self.get_physics_properties),
            rospy.Service("~set_physics_properties", SetPhysicsProperties, self.set_physics_properties),
            rospy.Subscriber("~set_model_state", ModelState, self.on_model_state, queue_size=10),
        ]

    def reset_world(self, _request):
        self._sim.reset_world()
        self._sim.world_changed("reset_world")
        return EmptyResponse()

    def reset_simulation(self, _request):
        self._sim.reset_simulation()
        self._sim.world_changed("reset_simulation")
        return EmptyResponse()

    def pause_physics(self, _request):
        self._sim.pause()
        self._sim.world_changed("pause_physics")
        return EmptyResponse()

    def unpause_physics(self, _request):
        self._sim.unpause()
        self._sim.world_changed("unpause_physics")
        return EmptyResponse()

    def spawn_sdf_model(self, request):
        return self._spawn(request, urdf_only=False)

    def spawn_urdf_model(self, request):
        return self._spawn(request, urdf_only=True)

    def _spawn(self, request, urdf_only):
        try:
            spec = parse_model_xml(request.model_xml, urdf_only)
            name = request.model_name or spec.name
            if not name:
                raise ModelXmlError("no model name: set model_name or the model's name attribute")
            initial = _finite_pose(request.initial_pose, "initial_pose")
            with self._sim.locked_world() as world:
                frame = frame_state(world, request.reference_frame)
                pose, _ = to_world(frame, compose(initial, spec.pose), Twist2D())
                pose = _within_world(pose, "initial_pose")
                if not isinstance(spec, TurtleBot3Spec):
                    world.spawn_model(replace(spec, name=name, pose=pose))
            if isinstance(spec, TurtleBot3Spec):
                self._sim.spawn_robot(name, spec.model, pose, request.robot_namespace)
        except SimError as error:
            return SpawnModelResponse(False, self._failed("SpawnModel", error))
        self._sim.world_changed("spawn_model", name)
        rospy.loginfo(f"spawned '{name}' at ({pose.x:.3f}, {pose.y:.3f}, yaw {pose.yaw:.3f})")
        return SpawnModelResponse(True, SPAWNED)

    def delete_model(self, request):
        try:
            with self._sim.locked_world() as world:
                world.delete_model(request.model_name)
        except SimError as error:
            return DeleteModelResponse(False, self._failed("DeleteModel", error))
        self._sim.world_changed("delete_model", request.model_name)
        return DeleteModelResponse(True, DELETED)

    def get_model_state(self, request):
        response = GetModelStateResponse()
        try:
            with self._sim.locked_world() as world:
                state = world.get_model_state(request.model_name)
                frame = frame_state(world, request.relative_entity_name)
                now_s = world.time_s
                calls = self._get_model_state_calls.get(request.model_name, 0) + 1
                self._get_model_state_calls[request.model_name] = calls
        except SimError as error:
            response.success, response.status_message = False, self._failed("GetModelState", error)
            return response
        response.header.seq = calls
        response.header.stamp = messages.stamp(now_s)
        response.header.frame_id = request.relative_entity_name
        pose, twist = from_world(frame, state.pose, state.twist)
        response.pose = messages.pose_message(pose)
        response.twist = messages.twist_message(twist)
        response.success, response.status_message = True, GOT_MODEL_STATE
        return response

    def set_model_state(self, request):
        state = request.model_state
        try:
            pose = _finite_pose(state.pose, "pose")
            twist = _finite_twist(state.twist)
            with self._sim.locked_world() as world:
                world.get_model_state(state.model_name)
                pose, twist = to_world(frame_state(world, state.reference_frame), pose, twist)
                world.set_model_state(state.model_name, _within_world(pose, "pose"), twist)
                self._sim.teleported()
        except SimError as error:
            return SetModelStateResponse(False, self._failed("SetModelState", error))
        self._sim.world_changed("set_model_state", state.model_name)
        return SetModelStateResponse(True, SET_MODEL_STATE)

    def on_model_state(self, message):
        """The /gazebo/set_model_state topic: the service without a reply (failures are logged)."""
        self.set_model_state(SetModelStateRequest(model_state=message))

    def get_world_properties(self, _request):
        with self._sim.locked_world() as world:
            return GetWorldPropertiesResponse(sim_time=world.time_s, model_names=world.model_names(),
                                              rendering_enabled=self._sim.rendering_enabled, success=True,
                                              status_message=GOT_WORLD_PROPERTIES)

    def get_physics_properties(self, _request):
        properties = self._sim.physics_properties
        return GetPhysicsPropertiesResponse(time_step=properties.time_step_s, pause=self._sim.paused,
                                            max_update_rate=properties.max_update_rate_hz,
                                            gravity=Vector3(*properties.gravity), ode_config=self._ode_config,
                                            success=True, status_message=GOT_PHYSICS_PROPERTIES)

    def set_physics_properties(self, request):
        gravity = request.gravity
        try:
            properties = physics_properties(request.time_step, request.max_update_rate,
                                            (gravity.x, gravity.y, gravity.z))
        except SimError as error:
            return SetPhysicsPropertiesResponse(False, self._failed("SetPhysicsProperties", error))
        self._ode_config = request.ode_config
        self._sim.set_physics_properties(properties)
        self._sim.world_changed("set_physics_properties")
        rospy.loginfo(f"physics properties set: real-time factor {properties.real_time_factor:g}"
                      f"{' (as fast as possible)' if properties.real_time_factor == 0 else ''}")
        return SetPhysicsPropertiesResponse(True, SET_PHYSICS_PROPERTIES)

    @staticmethod
    def _failed(service, error):
        message = failure_message(service, error)
        rospy.logwarn(message if str(error) in message else f"{message} ({error})")
        return message


def _finite_pose(message, field):
    values = (message.position.x, message.position.y, message.orientation.x, message.orientation.y,
              message.orientation.z, message.orientation.w)
    if not all(math.isfinite(v) for v in values):
        raise BadRequestError(f"{field} must hold finite numbers")
    return messages.pose_from_message(message)


def _within_world(pose, field):
    """`pose` (world frame) if it is finite and within MAX_COORDINATE_M of the origin."""
    if not all(math.isfinite(v) for v in pose):
        raise BadRequestError(f"{field} does not give a finite pose")
    if max(abs(pose.x), abs(pose.y)) > MAX_COORDINATE_M:
        raise BadRequestError(f"{field} puts the model at ({pose.x:g}, {pose.y:g}); tb3_sim accepts positions "
                              f"within ±{MAX_COORDINATE_M:g} m of the origin")
    return pose


def _finite_twist(message):
    linear, angular = (message.linear.x, message.linear.y), message.angular.z
    if not all(math.isfinite(v) for v in (*linear, angular)):
        raise BadRequestError("twist must hold finite numbers")
    if max(abs(v) for v in linear) > MAX_SPEED_MPS or abs(angular) > MAX_YAW_RATE_RADPS:
        raise BadRequestError(f"twist is beyond the sanity limits of ±{MAX_SPEED_MPS:g} m/s and "
                              f"±{MAX_YAW_RATE_RADPS:g} rad/s")
    return messages.twist_from_message(message)
