"""The ROS 2 Services unit, ported to ROS 1, against tb3_sim (empty world, sim time at 3x): each service has
the course's name and type, produces the specified motion measured on /odom, and refuses bad requests
without motion.

The course's command lines themselves (`rosservice type`, `rosrun <package> <client>`, typed as the README shows
them) run in test_readme_commands.py. Here the services and clients are under test, so the types come from
rosservice's Python API and a client runs as the file rosrun would run (roslab.master.node_path): each
`rosservice` or `rosrun` on the command line is one or three more Python starts (rosrun's package search runs
catkin_find twice), 0.5-1 CPU s each while the simulator runs beside them."""
import math
import subprocess
import time

import pytest
import rospy
import rosservice
from custom_interfaces.srv import Move, MyCustomServiceMessage, StringServiceMessage
from services_quiz_srv.srv import Turn
from std_srvs.srv import Empty, SetBool

from roslab import wait_for_param, wait_for_service, wait_for_topic, wait_until
from roslab.launch_args import CHEAP_CAMERA
from roslab.master import node_path
from roslab.robot_view import RobotView, angle_between

SERVERS = [("exercise42_pkg", "moving_right_server.py", "/moving_right"),
           ("movement_pkg", "movement_server.py", "/movement"),
           ("movement_pkg", "move_server.py", "/move"),
           ("services_quiz", "turn_server.py", "/turn"),
           ("fruit_detector_pkg", "detect_fruit_node.py", "/detect_fruit_service")]
TYPES = {"/moving": "std_srvs/Empty", "/stop": "std_srvs/Empty", "/moving_right": "std_srvs/SetBool",
         "/movement": "custom_interfaces/MyCustomServiceMessage", "/move": "custom_interfaces/Move",
         "/turn": "services_quiz_srv/Turn", "/detect_fruit_service": "custom_interfaces/StringServiceMessage"}
RAMP_SIM_S = 1.0   # sim seconds for the wheels to reach a commanded speed (they ramp at 1 m/s^2)


@pytest.fixture(scope="module")
def robot(ros_master):
    ros_master.roslaunch("course_sim_services", "course_sim_services.launch", "gui:=false",
                         "real_time_factor:=3", *CHEAP_CAMERA)
    assert wait_for_param(ros_master.uri, "/use_sim_time") is True   # before the servers read it
    for package, executable, _ in SERVERS:
        ros_master.rosrun(package, executable)
    for name in TYPES:
        wait_for_service(ros_master.uri, name, timeout_s=60)
    wait_for_topic(ros_master.uri, "/odom")
    return RobotView(ros_master.probe())


@pytest.fixture(autouse=True)
def stopped(robot):
    rospy.ServiceProxy("/stop", Empty)()
    robot.probe.sleep_sim(RAMP_SIM_S)


def velocity(robot):
    """(linear m/s, angular rad/s) from the next /odom twist."""
    robot.probe.take("/odom")
    twist = robot.probe.wait_for_message("/odom")["twist"]["twist"]
    return twist["linear"]["x"], twist["angular"]["z"]


def run(ros_master, package, executable, *args, timeout_s=60):
    """(exit code, stdout and stderr) of what `rosrun package executable args` runs, run to its end."""
    result = subprocess.run([node_path(package, executable), *args], env=ros_master.env, stdout=subprocess.PIPE,
                            stderr=subprocess.STDOUT, text=True, timeout=timeout_s)
    return result.returncode, result.stdout


@pytest.mark.parametrize("name", sorted(TYPES))
def test_service_names_and_types(robot, name):
    assert rosservice.get_service_type(name) == TYPES[name]


def test_service_client_starts_and_stop_client_stops_the_robot(ros_master, robot):
    code, output = run(ros_master, "client_pkg", "service_client.py")
    assert code == 0 and "the robot is moving" in output
    robot.probe.sleep_sim(RAMP_SIM_S)
    assert velocity(robot) == pytest.approx((0.3, 0.3), abs=0.01)
    code, output = run(ros_master, "client_pkg", "stop_client.py")
    assert code == 0 and "the robot is stopped" in output
    robot.probe.sleep_sim(RAMP_SIM_S)
    assert velocity(robot) == pytest.approx((0.0, 0.0), abs=0.01)


def test_service_client_waits_politely_for_a_missing_service(ros_master, robot):
    client = ros_master.rosrun("client_pkg", "service_client.py", "/moving:=/not_started_yet")
    wait_until(lambda: client.output().count("waiting again...") >= 2, 30, "two 'waiting again' lines")
    assert client.running()
    client.stop()
    assert "Traceback" not in client.output()


def test_moving_right(robot):
    reply = rospy.ServiceProxy("/moving_right", SetBool)(True)
    assert (reply.success, reply.message) == (True, "MOVING TO THE RIGHT RIGHT RIGHT!")
    robot.probe.sleep_sim(RAMP_SIM_S)
    assert velocity(robot) == pytest.approx((0.3, -0.3), abs=0.01)
    reply = rospy.ServiceProxy("/moving_right", SetBool)(False)
    assert (reply.success, reply.message) == (False, "It is time to stop!")
    robot.probe.sleep_sim(RAMP_SIM_S)
    assert velocity(robot) == pytest.approx((0.0, 0.0), abs=0.01)


@pytest.mark.parametrize("move, expected", [("Turn Left", (0.1, 0.5)), ("Turn Right", (0.1, -0.5))])
def test_movement_words_set_the_velocity(robot, move, expected):
    assert rospy.ServiceProxy("/movement", MyCustomServiceMessage)(move).success is True
    robot.probe.sleep_sim(RAMP_SIM_S)
    assert velocity(robot) == pytest.approx(expected, abs=0.01)


def test_movement_refuses_other_words_without_motion(robot):
    assert rospy.ServiceProxy("/movement", MyCustomServiceMessage)("Jump").success is False
    robot.probe.sleep_sim(RAMP_SIM_S)
    assert velocity(robot) == pytest.approx((0.0, 0.0), abs=0.001)


@pytest.mark.parametrize("executable", ["movement_client", "movement_client.py"])
def test_movement_client(ros_master, robot, executable):
    code, output = run(ros_master, "movement_pkg", executable, "Stop")
    assert code == 0 and "Result of the call to /movement: success = True" in output
    code, output = run(ros_master, "movement_pkg", executable)
    assert code == 1 and 'usage: rosrun movement_pkg movement_client "<move>"' in output


def test_movement_client_with_a_direction_calls_move(ros_master, robot):
    before = robot.pose()
    code, output = run(ros_master, "movement_pkg", "movement_client", "left", "0.2", "2")
    assert code == 0 and "Result of the call to /move: success = True" in output, output
    after = robot.settled_pose()
    assert angle_between(before[2], after[2]) == pytest.approx(0.4, abs=0.05)


def test_move_drives_for_the_given_time_then_stops(robot):
    before = robot.pose()
    assert rospy.ServiceProxy("/move", Move)("forward", 0.2, 2).success is True
    after = robot.settled_pose()
    ahead = (after[0] - before[0]) * math.cos(before[2]) + (after[1] - before[1]) * math.sin(before[2])
    assert ahead == pytest.approx(0.4, rel=0.05)
    robot.probe.sleep_sim(RAMP_SIM_S)
    assert velocity(robot)[0] == pytest.approx(0.0, abs=0.002)


@pytest.mark.parametrize("direction, speed, seconds", [("up", 0.2, 2), ("forward", 0.2, 0), ("left", 0.2, -1),
                                                       ("forward", 5.0, 2)])
def test_move_refuses_bad_requests_without_motion(robot, direction, speed, seconds):
    before = robot.pose()
    assert rospy.ServiceProxy("/move", Move)(direction, speed, seconds).success is False
    robot.probe.sleep_sim(RAMP_SIM_S)
    after = robot.settled_pose()
    assert abs(after[0] - before[0]) < 0.002 and abs(after[1] - before[1]) < 0.002


def test_turn_right_for_ten_seconds(robot):
    before = robot.pose()
    assert rospy.ServiceProxy("/turn", Turn)("right", 0.2, 10).success is True
    after = robot.settled_pose()
    assert angle_between(before[2], after[2]) == pytest.approx(-2.0, abs=0.1)
    robot.probe.sleep_sim(RAMP_SIM_S)
    assert velocity(robot)[1] == pytest.approx(0.0, abs=0.002)


def test_turn_refuses_a_bad_direction(robot):
    assert rospy.ServiceProxy("/turn", Turn)("around", 0.2, 2).success is False


def test_quiz_client_exits_0_after_the_motion(ros_master, robot):
    before = robot.pose()
    code, output = run(ros_master, "services_quiz", "turn_client.py")
    after = robot.settled_pose()
    assert code == 0, output
    assert angle_between(before[2], after[2]) == pytest.approx(-2.0, abs=0.1)


def test_fruit_service_answers_from_the_camera_and_publishes(robot):
    """The empty world holds no fruit: both are reported not in view, and the annotated frame is published;
    (fruit_world answers are tested in tests/integration/fruit_detector_pkg)."""
    robot.probe.subscribe("/image_detected_fruit", "sensor_msgs/Image")
    detect = rospy.ServiceProxy("/detect_fruit_service", StringServiceMessage)
    wait_until(lambda: "camera image" not in detect("apple").message, 30, "the detector's first camera image")
    assert (detect("apple").success, detect("banana").message) == (False, "no banana in view")
    image = robot.probe.wait_for_message("/image_detected_fruit", timeout_s=10)
    assert image["encoding"] == "bgr8"
    unknown = detect("kiwi")
    assert (unknown.success, unknown.message) == (False, "unknown fruit 'kiwi': detect must be apple or banana")


def test_parameter_clients_change_what_the_node_logs(ros_master, robot):
    node = ros_master.rosrun("python_parameters", "parameters_node")
    wait_for_service(ros_master.uri, "/minimal_param_node/get_loggers")
    code, output = run(ros_master, "python_parameters", "get_parameters_client")
    assert code == 0 and "/minimal_param_node/my_parameter = world" in output
    code, output = run(ros_master, "python_parameters", "set_parameters_client", "my_parameter", "earth")
    assert code == 0, output
    set_at = time.monotonic()
    while "my_parameter: earth" not in node.output():
        assert time.monotonic() - set_at < 2.0, node.output()[-500:]
        time.sleep(0.05)
    code, output = run(ros_master, "python_parameters", "set_parameters_client", "their_parameter", "x")
    assert code == 1 and "usage:" in output
