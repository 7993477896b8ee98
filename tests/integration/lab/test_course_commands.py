"""The course pages' commands, run verbatim against a private master: rossrv show, rosservice call/info
on a tiny rospy SetBool server, and a Python client round trip."""
import subprocess

import pytest
import rospy
from tuos_msgs.srv import SetBool

from roslab import wait_for_service


def run(command, master, timeout_s=30):
    result = subprocess.run(command, env=master.env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                            text=True, timeout=timeout_s)
    return result.returncode, result.stdout


@pytest.fixture(scope="module")
def echo_server(ros_master):
    ros_master.rosrun("tuos_msgs", "set_bool_echo_server.py")
    wait_for_service(ros_master.uri, "/echo_set_bool")
    return "/echo_set_bool"


@pytest.mark.parametrize("package", ["tuos_msgs", "com2009_msgs", "tuos_ros_msgs"])
def test_rossrv_show_prints_the_fields(ros_master, package):
    code, output = run(["rossrv", "show", package + "/SetBool"], ros_master)
    assert code == 0, output
    assert output.split("\n")[:4] == ["bool request_signal", "---", "bool response_signal",
                                      "string response_message"]


def test_rosservice_call_round_trip(ros_master, echo_server):
    code, output = run(["rosservice", "call", echo_server, "request_signal: true"], ros_master)
    assert code == 0, output
    assert "response_signal: True" in output
    assert 'response_message: "received True"' in output


def test_rosservice_info_names_node_type_and_args(ros_master, echo_server):
    code, output = run(["rosservice", "info", echo_server], ros_master)
    assert code == 0, output
    assert "Node: /set_bool_echo_server" in output
    assert "Type: tuos_msgs/SetBool" in output
    assert "Args: request_signal" in output


def test_python_client_round_trip(ros_master, echo_server):
    reply = rospy.ServiceProxy(echo_server, SetBool)(False)
    assert (reply.response_signal, reply.response_message) == (False, "received False")


def test_calling_a_missing_service_is_a_clear_error(ros_master):
    code, output = run(["rosservice", "call", "/no_such_service", "request_signal: true"], ros_master)
    assert code != 0
    assert "ERROR: Service [/no_such_service] is not available." in output
