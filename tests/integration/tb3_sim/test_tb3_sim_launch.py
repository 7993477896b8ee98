"""The course's launch commands start tb3_sim: `roslaunch turtlebot3_gazebo turtlebot3_empty_world.launch` and
turtlebot3_world.launch (model named from TURTLEBOT3_MODEL, spawn pose defaults), the tb3_* aliases, and
`real_time_factor` pacing. One simulator at a time on this module's master (each test ends its own); the robot of
the empty world and of the world with the original args is also driven, so that no simulator is started only for
that."""
import subprocess
import time
from pathlib import Path

import pytest
import rosgraph
import rospy
from gazebo_msgs.srv import GetModelState, GetWorldProperties

from roslab import wait_for_service, wait_for_service_gone, wait_until

REPO_ROOT = Path(__file__).resolve().parents[3]


def robot_position(name):
    reply = rospy.ServiceProxy("/gazebo/get_model_state", GetModelState)(model_name=name, relative_entity_name="")
    assert reply.success, reply.status_message
    return reply.pose.position.x, reply.pose.position.y


def model_names():
    return rospy.ServiceProxy("/gazebo/get_world_properties", GetWorldProperties)().model_names


def assert_the_robot_answers_cmd_vel_with_odom_and_scan(probe):
    """A 360-beam /scan, and /odom moving 0.1 m forward under 0.2 m/s on /cmd_vel (messages of an earlier
    simulator dropped first)."""
    probe.subscribe("/odom", "nav_msgs/Odometry")
    probe.subscribe("/scan", "sensor_msgs/LaserScan")
    probe.take("/odom")
    probe.take("/scan")
    x0 = probe.wait_for_message("/odom")["pose"]["pose"]["position"]["x"]
    assert len(probe.wait_for_message("/scan")["ranges"]) == 360
    probe.publish("/cmd_vel", "geometry_msgs/Twist", {"linear": {"x": 0.2}})
    probe.wait_for_message("/odom", predicate=lambda m: m["pose"]["pose"]["position"]["x"] > x0 + 0.1)
    probe.publish("/cmd_vel", "geometry_msgs/Twist", {})


def test_empty_world_launch_without_turtlebot3_model_set_or_a_display(launch, probe):
    """Where the course's Gazebo window would open, one line says how to see the world here."""
    process = launch("turtlebot3_gazebo", "turtlebot3_empty_world.launch",
                     unset=("TURTLEBOT3_MODEL", "DISPLAY", "WAYLAND_DISPLAY", "QT_QPA_PLATFORM"))
    assert model_names() == ["ground_plane", "turtlebot3_waffle"]
    assert robot_position("turtlebot3_waffle") == pytest.approx((0.0, 0.0))
    hint = "[tb3_sim] no display, so the simulator's window (Gazebo's gzclient in the course) is not started. See it"
    assert process.output().count(hint) == 1 and "lab_web web.launch" in process.output()
    assert_the_robot_answers_cmd_vel_with_odom_and_scan(probe)


def test_world_launch_spawns_at_the_original_defaults_named_after_the_model(launch):
    launch("turtlebot3_gazebo", "turtlebot3_world.launch", TURTLEBOT3_MODEL="burger")
    assert model_names() == ["ground_plane", "ros_symbol", "turtlebot3_burger"]
    assert robot_position("turtlebot3_burger") == pytest.approx((-2.0, -0.5))


def test_world_launch_takes_the_original_args(launch, probe):
    launch("turtlebot3_gazebo", "turtlebot3_world.launch", "model:=waffle", "x_pos:=-1.5", "y_pos:=0.5",
           "z_pos:=0.3")
    assert robot_position("turtlebot3_waffle") == pytest.approx((-1.5, 0.5))
    assert_the_robot_answers_cmd_vel_with_odom_and_scan(probe)   # 0.1 m towards x, clear of the pillars


def test_real_time_factor_5_runs_10_sim_seconds_in_about_2_wall_seconds(launch, ros_master):
    launch("tb3_sim", "tb3_sim.launch", "real_time_factor:=5")
    world_properties = rospy.ServiceProxy("/gazebo/get_world_properties", GetWorldProperties)
    start_sim, start_wall = world_properties().sim_time, time.monotonic()
    wait_until(lambda: world_properties().sim_time >= start_sim + 10.0, 30, "10 s of sim time", interval_s=0.02)
    elapsed = time.monotonic() - start_wall
    assert 1.0 < elapsed < 6.0


@pytest.mark.parametrize("args, clock_rate", [
    ((), None), (("use_clock_frequency:=true", "pub_clock_frequency:=50"), 50.0)])
def test_empty_world_takes_gazebos_clock_frequency_args(ros_master, args, clock_rate):
    dump = subprocess.run(["roslaunch", "--dump-params", "gazebo_ros", "empty_world.launch", *args],
                          env=ros_master.env, capture_output=True, text=True, timeout=60).stdout
    assert "/gazebo/spawn_robot: false" in dump
    assert ("/gazebo/clock_rate: 100.0" if clock_rate is None else f"/gazebo/clock_rate: {clock_rate}") in dump


@pytest.mark.parametrize("alias", ["tb3_empty_world", "tb3_world"])
def test_course_aliases_exist(alias):
    result = subprocess.run(["bash", "-c", f"source scripts/env.sh >/dev/null && alias {alias}"], cwd=REPO_ROOT,
                            stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, timeout=60)
    assert result.returncode == 0, result.stdout
    launch_file = alias.replace("tb3_", "turtlebot3_") + ".launch"
    assert f"roslaunch turtlebot3_gazebo {launch_file}" in result.stdout


def test_spawn_box_without_a_simulator_fails_clearly(ros_master):
    result = subprocess.run(["rosrun", "tb3_sim", "spawn_box", "box1", "1", "0", "--timeout", "1"],
                            env=ros_master.env, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, timeout=60)
    assert result.returncode == 1
    assert result.stderr == ("spawn_box: /gazebo/spawn_sdf_model is not available after 1 s; is the simulator "
                             "running?\n")


def test_approach_arena_scan_sees_the_target_box_ahead(launch, ros_master):
    launch("turtlebot3_gazebo", "turtlebot3_approach_arena.launch")
    probe = ros_master.probe()
    try:
        probe.subscribe("/scan", "sensor_msgs/LaserScan")
        scan = probe.wait_for_message("/scan")
    finally:
        probe.stop()
    assert scan["ranges"][0] == pytest.approx(1.3 + 0.064, abs=0.04)
    assert scan["ranges"][180] == pytest.approx(1.0 - 0.064, abs=0.04)


@pytest.mark.parametrize("param, message", [
    ("_world:=nowhere", "tb3_sim: ~world: no world file"),
    ("_real_time_factor:=-2", "tb3_sim: ~real_time_factor must be >= 0.0, got -2"),
])
def test_bad_parameters_stop_the_node_with_one_clear_line(ros_master, param, message):
    node_name = "__name:=bad_" + param.split(":=")[0].strip("_")
    result = subprocess.run(["rosrun", "tb3_sim", "tb3_sim_node", param, node_name], env=ros_master.env,
                            stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, timeout=60)
    assert result.returncode == 1
    assert message in result.stdout
    assert "Traceback" not in result.stdout


def test_a_broken_world_file_names_file_and_key(ros_master, tmp_path):
    world = tmp_path / "broken.yaml"
    world.write_text("name: broken\nmodels:\n  - {name: b, type: box, size: [1, 1]}\n")
    result = subprocess.run(["rosrun", "tb3_sim", "tb3_sim_node", f"_world:={world}", "__name:=broken_world"],
                            env=ros_master.env,
                            stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, timeout=60)
    assert result.returncode == 1
    assert f"{world}: models[0].size: expected a list of 3 numbers" in result.stdout
    assert "Traceback" not in result.stdout


def test_a_restarted_roscore_gets_the_simulator_and_use_sim_time_back(launch, ros_master):
    launch("tb3_sim", "tb3_sim.launch")
    ros_master.restart_core()
    wait_for_service(ros_master.uri, "/gazebo/get_world_properties", timeout_s=10)
    assert wait_until(lambda: _param(ros_master, "/use_sim_time"), 10, "/use_sim_time on the new master")
    assert model_names() == ["ground_plane", "turtlebot3_waffle"]


def _param(ros_master, name):
    master = rosgraph.Master("/test", master_uri=ros_master.uri)
    return master.hasParam(name) and master.getParam(name)


def test_with_a_display_the_window_opens_and_physics_runs_beside_it(ros_master):
    xvfb = ros_master.start(["Xvfb", "-displayfd", "1", "-screen", "0", "800x600x24", "-nolisten", "tcp"], "xvfb")
    display = wait_until(lambda: xvfb.output().strip(), 20, "Xvfb to choose a display")
    process = ros_master.start(["env", "-u", "QT_QPA_PLATFORM", f"DISPLAY=:{display}", "roslaunch", "--wait",
                                "tb3_sim", "tb3_sim.launch", "world:=turtlebot3_world", "x_pos:=-2.0",
                                "y_pos:=-0.5"], "tb3_sim_window")
    try:
        wait_for_service(ros_master.uri, "/gazebo/get_world_properties", timeout_s=30)
        world_properties = rospy.ServiceProxy("/gazebo/get_world_properties", GetWorldProperties)
        wait_until(lambda: world_properties().rendering_enabled, 20, "the window to open")
        first = world_properties()
        wait_until(lambda: world_properties().sim_time > first.sim_time + 0.5, 10, "sim time to advance")
    finally:
        process.stop()
        xvfb.stop()
    wait_for_service_gone(ros_master.uri, "/gazebo/get_world_properties")
    assert "Traceback" not in process.output()
