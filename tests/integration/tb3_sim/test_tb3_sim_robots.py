"""Robots the TurtleBot3 way: `roslaunch gazebo_ros empty_world.launch` plus `spawn_model -urdf -param
robot_description` gives the topics turtlebot3_empty_world.launch gives; multi_turtlebot3.launch's three robots
drive independently in their namespaces and collide with each other; wheel joint angles turn by distance / wheel
radius; /gazebo/set_physics_properties changes the measured real-time factor. One launch at a time on the
module's master (each test ends its own; the `launch` fixture is in this folder's conftest)."""
import subprocess
import time
from pathlib import Path

import pytest
import rosgraph
import rospkg
import rospy
from gazebo_msgs.msg import ODEPhysics
from gazebo_msgs.srv import (
    GetModelState,
    GetPhysicsProperties,
    GetWorldProperties,
    SetModelState,
    SetModelStateRequest,
    SetPhysicsProperties,
    SpawnModel,
    SpawnModelRequest,
)
from geometry_msgs.msg import Vector3

from roslab import wait_for_service_gone, wait_until

WAFFLE_XACRO = "$(find turtlebot3_description)/urdf/turtlebot3_waffle.urdf.xacro"
ROBOT_TOPICS = ("cmd_vel", "odom", "scan", "imu", "joint_states", "camera/rgb/image_raw", "camera/depth/image_raw")


def _published_topics(ros_master):
    """{topic: type} of the topics that have a publisher or a subscriber now."""
    master = rosgraph.Master("/test", master_uri=ros_master.uri)
    publications, subscriptions, _ = master.getSystemState()
    live = {topic for topic, _ in publications + subscriptions}
    return {topic: kind for topic, kind in master.getTopicTypes() if topic in live}


def sim_time():
    return rospy.ServiceProxy("/gazebo/get_world_properties", GetWorldProperties)().sim_time


def model_names():
    return rospy.ServiceProxy("/gazebo/get_world_properties", GetWorldProperties)().model_names


def wait_for_models(*names):
    wait_until(lambda: set(names) <= set(model_names()), 30, f"models {names} to be spawned")


def position(name):
    reply = rospy.ServiceProxy("/gazebo/get_model_state", GetModelState)(model_name=name, relative_entity_name="")
    assert reply.success, reply.status_message
    return reply.pose.position.x, reply.pose.position.y


def robot_topics(ros_master, namespace="/"):
    types = _published_topics(ros_master)
    return {topic: types.get(namespace + topic) for topic in ROBOT_TOPICS}


def test_empty_world_plus_spawn_model_gives_the_topics_of_turtlebot3_empty_world(launch, ros_master, tmp_path):
    first = launch("turtlebot3_gazebo", "turtlebot3_empty_world.launch", "gui:=false", TURTLEBOT3_MODEL="waffle")
    wait_for_models("turtlebot3_waffle")
    expected = robot_topics(ros_master)
    assert all(expected.values()), expected
    first.stop()
    wait_for_service_gone(ros_master.uri, "/gazebo/get_world_properties")

    (tmp_path / "spawn.launch").write_text(f"""<launch>
  <include file="$(find gazebo_ros)/launch/empty_world.launch"><arg name="gui" value="false"/></include>
  <param name="robot_description" command="$(find xacro)/xacro --inorder {WAFFLE_XACRO}"/>
  <node pkg="gazebo_ros" type="spawn_model" name="spawn_urdf"
        args="-urdf -model turtlebot3_waffle -x 0.5 -y 0.2 -param robot_description"/>
</launch>""")
    launch(str(tmp_path / "spawn.launch"), TURTLEBOT3_MODEL="waffle")
    assert model_names() in (["ground_plane"], ["ground_plane", "turtlebot3_waffle"])
    wait_for_models("turtlebot3_waffle")
    assert position("turtlebot3_waffle") == pytest.approx((0.5, 0.2))
    assert robot_topics(ros_master) == expected


def test_multi_turtlebot3_robots_drive_independently_and_collide(launch, probe):
    launch("turtlebot3_gazebo", "multi_turtlebot3.launch", "gui:=false", "real_time_factor:=4",
           robot_topic="/tb3_2/odom", TURTLEBOT3_MODEL="waffle")
    wait_for_models("tb3_0", "tb3_1", "tb3_2")
    names = model_names()
    assert names[:2] == ["ground_plane", "turtlebot3_house"] and sorted(names[2:]) == ["tb3_0", "tb3_1", "tb3_2"]
    starts = {name: position(name) for name in ("tb3_0", "tb3_1", "tb3_2")}
    assert starts == {"tb3_0": pytest.approx((-7.0, -1.0)), "tb3_1": pytest.approx((7.0, -1.0)),
                      "tb3_2": pytest.approx((0.5, 3.0))}
    probe.subscribe("/tb3_1/odom", "nav_msgs/Odometry")
    probe.subscribe("/tb3_2/scan", "sensor_msgs/LaserScan")
    odom = probe.wait_for_message("/tb3_1/odom")
    assert (odom["header"]["frame_id"], odom["child_frame_id"]) == ("tb3_1/odom", "tb3_1/base_footprint")
    assert probe.wait_for_message("/tb3_2/scan")["header"]["frame_id"] == "tb3_2/base_scan"

    # tb3_2 alone drives (facing +x) for 1 s of sim time at 0.2 m/s; the others stay where they are.
    probe.publish("/tb3_2/cmd_vel", "geometry_msgs/Twist", {"linear": {"x": 0.2}})
    wait_until(lambda: position("tb3_2")[0] > starts["tb3_2"][0] + 0.2, 30, "tb3_2 to move 0.2 m")
    probe.publish("/tb3_2/cmd_vel", "geometry_msgs/Twist", {})
    assert position("tb3_0") == pytest.approx(starts["tb3_0"], abs=1e-3)
    assert position("tb3_1") == pytest.approx(starts["tb3_1"], abs=1e-3)

    # tb3_1 is put 0.6 m ahead of tb3_2 facing it; tb3_2 drives into it and stops at its body, not through it.
    x2, y2 = position("tb3_2")
    request = SetModelStateRequest()
    request.model_state.model_name = "tb3_1"
    request.model_state.pose.position.x, request.model_state.pose.position.y = x2 + 0.6, y2
    request.model_state.pose.orientation.z, request.model_state.pose.orientation.w = 1.0, 0.0
    assert rospy.ServiceProxy("/gazebo/set_model_state", SetModelState)(request).success
    probe.publish("/tb3_2/cmd_vel", "geometry_msgs/Twist", {"linear": {"x": 0.26}})
    sim_start = sim_time()
    wait_until(lambda: sim_time() > sim_start + 4.0, 30, "4 s of sim time")
    probe.publish("/tb3_2/cmd_vel", "geometry_msgs/Twist", {})
    x_front, _ = position("tb3_2")
    x_other, _ = position("tb3_1")
    # Waffle fronts are 0.069 m ahead of base_footprint: face to face they meet 0.138 m apart (less if pushed).
    assert x_other - x_front == pytest.approx(0.138, abs=0.05)


def test_wheel_joints_turn_by_distance_over_wheel_radius(launch, probe):
    launch("tb3_sim", "tb3_sim.launch", "gui:=false", "real_time_factor:=4", TURTLEBOT3_MODEL="waffle")
    probe.subscribe("/joint_states", "sensor_msgs/JointState")
    probe.subscribe("/odom", "nav_msgs/Odometry")
    first = probe.wait_for_message("/joint_states")
    x0 = probe.wait_for_message("/odom")["pose"]["pose"]["position"]["x"]
    probe.publish("/cmd_vel", "geometry_msgs/Twist", {"linear": {"x": 0.2}})
    wait_until(lambda: position("turtlebot3_waffle")[0] > x0 + 0.5, 30, "0.5 m of driving")
    probe.publish("/cmd_vel", "geometry_msgs/Twist", {})
    wait_until(lambda: abs(probe.wait_for_message("/odom")["twist"]["twist"]["linear"]["x"]) < 1e-3, 30,
               "the robot to stop")
    stopped_s = sim_time()
    last = probe.wait_for_message("/joint_states", predicate=lambda m: m["header"]["stamp"] >= stopped_s)
    distance = position("turtlebot3_waffle")[0] - x0
    assert last["name"] == ["wheel_left_joint", "wheel_right_joint"]
    for before, after in zip(first["position"], last["position"]):
        assert after - before == pytest.approx(distance / 0.033, rel=0.03)


def measured_real_time_factor(wall_s=2.0):
    properties = rospy.ServiceProxy("/gazebo/get_world_properties", GetWorldProperties)
    sim_start, wall_start = properties().sim_time, time.monotonic()
    time.sleep(wall_s)
    return (properties().sim_time - sim_start) / (time.monotonic() - wall_start)


def test_set_physics_properties_changes_the_real_time_factor(launch):
    launch("tb3_sim", "tb3_sim.launch", "gui:=false", TURTLEBOT3_MODEL="waffle")
    get = rospy.ServiceProxy("/gazebo/get_physics_properties", GetPhysicsProperties)
    set_ = rospy.ServiceProxy("/gazebo/set_physics_properties", SetPhysicsProperties)
    initial = get()
    assert (initial.success, initial.time_step, initial.max_update_rate, initial.pause) == (True, 0.005, 200.0, False)
    at_one = measured_real_time_factor()
    reply = set_(time_step=0.001, max_update_rate=4000.0, gravity=Vector3(0.0, 0.0, -9.8),
                 ode_config=initial.ode_config)
    assert (reply.success, reply.status_message) == (True, "physics engine updated")
    at_four = measured_real_time_factor()
    assert 0.7 < at_one < 1.2
    assert at_four / at_one == pytest.approx(4.0, rel=0.3)
    assert (get().time_step, get().max_update_rate) == (0.001, 4000.0)

    refused = set_(time_step=-0.001, max_update_rate=1000.0, gravity=Vector3(0.0, 0.0, -9.8), ode_config=ODEPhysics())
    assert not refused.success and "time_step" in refused.status_message
    assert get().max_update_rate == 4000.0


def test_a_second_robot_needs_its_own_namespace(launch, ros_master):
    launch("tb3_sim", "tb3_sim.launch", "gui:=false", TURTLEBOT3_MODEL="waffle")
    urdf = Path(rospkg.RosPack().get_path("turtlebot3_description")) / "urdf" / "turtlebot3_burger.urdf.xacro"
    xml = subprocess.run(["rosrun", "xacro", "xacro", str(urdf)], env=ros_master.env, capture_output=True, text=True,
                         timeout=60)
    assert xml.returncode == 0, xml.stderr
    spawn = rospy.ServiceProxy("/gazebo/spawn_urdf_model", SpawnModel)
    request = SpawnModelRequest(model_name="second", model_xml=xml.stdout, robot_namespace="/")
    request.initial_pose.position.x = 1.0
    request.initial_pose.orientation.w = 1.0
    reply = spawn(request)
    assert not reply.success and "namespace '/' is already used by robot 'turtlebot3_waffle'" in reply.status_message
    request.robot_namespace = "/second"
    reply = spawn(request)
    assert reply.success, reply.status_message
    assert model_names()[-1] == "second" and position("second") == pytest.approx((1.0, 0.0))
    assert _published_topics(ros_master).get("/second/odom") == "nav_msgs/Odometry"
    assert "/second/camera/rgb/image_raw" not in _published_topics(ros_master), "a Burger has no camera"
