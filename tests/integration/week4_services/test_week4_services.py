"""Week 4 services against tb3_sim (roslaunch week4_services week4_demo.launch), measured through /odom and
/scan: distances travelled, angles turned, stopping distances, and no motion on refused requests."""
import math
import subprocess
import time

import pytest
import rospy
from std_srvs.srv import Empty
from tuos_msgs.srv import Approach, SetBool, TimedMovement

from roslab import wait_for_service
from roslab.calls import BackgroundCall
from roslab.robot_view import RobotView, angle_between, pose_of

REAL_TIME_FACTOR = "3"
STILL_M = 0.002
STILL_SWEEPS = 5   # the stopped robot's distance to the box, as the median of this many LiDAR sweeps


@pytest.fixture(scope="module")
def robot(ros_master):
    ros_master.roslaunch("week4_services", "week4_demo.launch", "gui:=false",
                         "real_time_factor:=" + REAL_TIME_FACTOR)
    for name in ["/move_service", "/timed_move_service", "/approach_service", "/gazebo/reset_world"]:
        wait_for_service(ros_master.uri, name, timeout_s=60)
    return RobotView(ros_master.probe())


def at_spawn_pose(odom):
    x, y, yaw = pose_of(odom)
    return math.hypot(x, y) < 0.01 and abs(yaw) < 0.01


@pytest.fixture(autouse=True)
def start_from_spawn_pose(robot):
    """Every test starts with the robot back at the origin facing the box, and still."""
    robot.probe.take("/odom")   # messages from before the reset must not count as "back at spawn"
    rospy.ServiceProxy("/gazebo/reset_world", Empty)()
    robot.probe.wait_for_message("/odom", timeout_s=10, predicate=at_spawn_pose)


def call(name, srv_type, *args):
    return rospy.ServiceProxy(name, srv_type)(*args)


def distance(a, b):
    return math.hypot(b[0] - a[0], b[1] - a[1])


def assert_did_not_move(robot, before):
    time.sleep(0.5)
    after = robot.settled_pose()
    assert distance(before, after) < STILL_M and abs(angle_between(before[2], after[2])) < 0.002


def test_move_service_true_moves_half_a_metre(robot):
    before = robot.pose()
    reply = call("/move_service", SetBool, True)
    after = robot.settled_pose()
    assert reply.response_signal is True
    assert "complete" in reply.response_message
    assert distance(before, after) == pytest.approx(0.50, abs=0.03)
    assert after[0] > before[0]


def test_move_service_false_does_nothing(robot):
    before = robot.pose()
    reply = call("/move_service", SetBool, False)
    assert reply.response_signal is False
    assert "true" in reply.response_message
    assert_did_not_move(robot, before)


@pytest.mark.parametrize("word, metres", [("fwd", 0.20), ("back", -0.20)])
def test_timed_drive(robot, word, metres):
    before = robot.pose()
    assert call("/timed_move_service", TimedMovement, word, 2).success is True
    after = robot.settled_pose()
    assert after[0] - before[0] == pytest.approx(metres, rel=0.05)


@pytest.mark.parametrize("word, radians", [("left", 0.6), ("right", -0.6)])
def test_timed_turn(robot, word, radians):
    before = robot.pose()
    assert call("/timed_move_service", TimedMovement, word, 2).success is True
    after = robot.settled_pose()
    assert angle_between(before[2], after[2]) == pytest.approx(radians, rel=0.05)
    assert distance(before, after) < 0.01


@pytest.mark.parametrize("word, duration", [("forward", 2), ("", 2), ("fwd", 0), ("left", -1), ("back", 61)])
def test_timed_move_refuses_bad_requests_without_motion(robot, word, duration):
    before = robot.pose()
    started = time.monotonic()
    assert call("/timed_move_service", TimedMovement, word, duration).success is False
    assert time.monotonic() - started < 1.0
    assert_did_not_move(robot, before)


def test_a_second_timed_move_while_one_runs_is_refused_at_once(robot):
    """Requests never interleave: the second is refused at once, logs no "Moving" line, and the robot
    carries out the first alone."""
    robot.probe.subscribe("/rosout_agg", "rosgraph_msgs/Log")
    robot.probe.take("/rosout_agg")
    before = robot.pose()
    first = BackgroundCall("/timed_move_service", TimedMovement, "fwd", 2)
    robot.probe.wait_for_message("/odom", predicate=lambda odom: odom["twist"]["twist"]["linear"]["x"] > 0.05)
    started = time.monotonic()
    assert call("/timed_move_service", TimedMovement, "left", 1).success is False
    assert time.monotonic() - started < 1.0
    assert first.join(timeout_s=30) and first.reply.success is True
    after = robot.settled_pose()
    assert after[0] - before[0] == pytest.approx(0.20, rel=0.05)
    assert abs(angle_between(before[2], after[2])) < 0.01
    time.sleep(0.5)   # rosout relays the server's last lines
    logs = [entry["msg"] for entry in robot.probe.take("/rosout_agg")]
    lines = [log["msg"] for log in logs if log["name"] == "/timed_move_service_server"]
    assert [line for line in lines if line.startswith("Moving")] == ["Moving 'fwd' for 2 seconds..."], lines
    assert any("busy" in line for line in lines), lines


@pytest.mark.realtime   # the stopping distance depends on the server's control loop running on time
@pytest.mark.parametrize("velocity, tolerance", [(0.1, 0.02), (0.26, 0.04)])
def test_approach_stops_at_the_requested_distance(robot, velocity, tolerance):
    reply = call("/approach_service", Approach, 0.4, velocity)
    measured = robot.front_distance(sweeps=STILL_SWEEPS)
    assert measured == pytest.approx(0.40, abs=tolerance), reply.response_message
    assert reply.response_message.startswith("Stopped: the closest object ahead is")
    reported = float(reply.response_message.split(" is ")[1].split(" m")[0])
    assert reported == pytest.approx(measured, abs=0.03)


@pytest.mark.parametrize("distance_m, velocity, field", [
    (0.4, 0.0, "approach_velocity"), (0.4, 0.3, "approach_velocity"), (0.4, -0.1, "approach_velocity"),
    (0.1, 0.1, "approach_distance"), (3.5, 0.1, "approach_distance"), (math.nan, 0.1, "approach_distance"),
    (0.4, math.nan, "approach_velocity"),
])
def test_approach_refuses_bad_requests_without_motion(robot, distance_m, velocity, field):
    before = robot.pose()
    reply = call("/approach_service", Approach, distance_m, velocity)
    assert reply.response_message.startswith("Request failed: " + field)
    assert_did_not_move(robot, before)


def test_move_client_prints_the_response(ros_master, robot):
    result = subprocess.run(["rosrun", "week4_services", "move_client.py"], env=ros_master.env,
                            stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, timeout=60)
    assert result.returncode == 0, result.stdout
    assert "response_signal: True" in result.stdout
    assert "response_message: Request complete" in result.stdout


def run_cli(ros_master, *command):
    result = subprocess.run(list(command), env=ros_master.env, stdout=subprocess.PIPE,
                            stderr=subprocess.STDOUT, text=True, timeout=60)
    assert result.returncode == 0, result.stdout
    return result.stdout


def test_course_terminal_workflow(ros_master, robot):
    services = run_cli(ros_master, "rosservice", "list").split()
    assert {"/move_service", "/timed_move_service", "/approach_service"} <= set(services)
    info = run_cli(ros_master, "rosservice", "info", "/move_service")
    assert "Node: /move_service_server" in info
    assert "Type: tuos_msgs/SetBool" in info
    assert "Args: request_signal" in info
    assert run_cli(ros_master, "rossrv", "show", "tuos_msgs/TimedMovement").split("\n")[:4] == [
        "string movement_request", "int32 duration", "---", "bool success"]
    called = run_cli(ros_master, "rosservice", "call", "/timed_move_service",
                     "{movement_request: 'fwd', duration: 1}")
    assert "success: True" in called
