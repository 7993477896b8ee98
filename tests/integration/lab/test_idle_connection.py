"""An idle TCP connection to a rospy node's TCPROS port (a port scan, a stale client: the raw-socket probe) no
longer freezes the node: with three such connections open to the port `rosservice uri` names, a service call and a
new subscriber's handshake are answered within the lab's handshake timeout, for a lab node (the Week 4 approach
server), tb3_sim, turtlesim and a node written the way a student writes one (run with the lab's environment).
Unpatched rospy read each idle connection's handshake in its accept thread for 60 s, one after the other."""
import contextlib
import io
import socket
import threading
import time
from urllib.parse import urlsplit

import pytest
import rospy
from gazebo_msgs.srv import GetWorldProperties
from rosgraph.network import encode_ros_handshake_header, read_ros_handshake_header
from std_srvs.srv import Empty, Trigger
from tuos_msgs.srv import Approach

from roslab import wait_for_service
from rospy_handshake_timeout import HANDSHAKE_TIMEOUT_S

IDLE_CONNECTIONS = 3
ANSWER_WITHIN_S = HANDSHAKE_TIMEOUT_S + 5.0   # unpatched: 60 s per idle connection
STUDENT_NODE = """\
#!/usr/bin/env python3
import rospy
from std_srvs.srv import Trigger, TriggerResponse


def greet(_request):
    return TriggerResponse(success=True, message="hello")


rospy.init_node("student_node")
rospy.Service("student_service", Trigger, greet)
rospy.spin()
"""
# node: (a service it offers, its type, request fields)
NODES = {
    "approach_server": ("/approach_service", Approach, {"approach_distance": 0.4, "approach_velocity": 0.5}),
    "tb3_sim": ("/gazebo/get_world_properties", GetWorldProperties, {}),
    "turtlesim": ("/clear", Empty, {}),
    "student_node": ("/student_service", Trigger, {}),
}


@pytest.fixture(scope="module")
def graph(ros_master, tmp_path_factory):
    """The Week 4 demo (tb3_sim and the three servers), turtlesim and a student's node, on the module's master."""
    ros_master.roslaunch("week4_services", "week4_demo.launch", "gui:=false", "real_time_factor:=5")
    ros_master.rosrun("turtlesim", "turtlesim_node", "_headless:=true")
    student = tmp_path_factory.mktemp("student") / "student_node.py"
    student.write_text(STUDENT_NODE)
    ros_master.start(["python3", str(student)], "student_node")
    return {node: wait_for_service(ros_master.uri, service, timeout_s=60)
            for node, (service, _, _) in NODES.items()}


@contextlib.contextmanager
def idle_connections(rosrpc_uri, count=IDLE_CONNECTIONS):
    """`count` raw TCP connections to the node's TCPROS port that never send a byte, open for the block."""
    address = urlsplit(rosrpc_uri)
    sockets = [socket.create_connection((address.hostname, address.port), timeout=5) for _ in range(count)]
    try:
        time.sleep(0.5)   # accepted by the node before the test's own request comes
        yield address
    finally:
        for raw in sockets:
            raw.close()


def within(seconds, work, what):
    """`work()`'s result, failing the test if it takes longer than `seconds` (it is left to finish alone)."""
    result = {}

    def run():
        try:
            result["value"] = work()
        except Exception as error:   # noqa: BLE001 - reported below as the test's failure
            result["error"] = error
    thread = threading.Thread(target=run, daemon=True)
    started = time.monotonic()
    thread.start()
    thread.join(seconds)
    assert not thread.is_alive(), "{} still waiting after {:.0f} s".format(what, time.monotonic() - started)
    assert "error" not in result, "{}: {!r}".format(what, result.get("error"))
    return result["value"]


def subscribe_handshake(address, topic="/rosout"):
    """What a new subscriber does first: send its connection header for `topic` (every rospy node publishes
    /rosout) and read the publisher's reply header."""
    with socket.create_connection((address.hostname, address.port), timeout=60) as raw:
        raw.sendall(encode_ros_handshake_header({"callerid": "/idle_probe", "topic": topic, "md5sum": "*",
                                                 "type": "*", "tcp_nodelay": "1"}))
        return read_ros_handshake_header(raw, io.BytesIO(), 4096)


@pytest.mark.parametrize("node", NODES)
def test_a_service_call_is_answered_while_idle_connections_are_open(graph, node):
    service, service_class, fields = NODES[node]
    with idle_connections(graph[node]):
        within(ANSWER_WITHIN_S, lambda: rospy.ServiceProxy(service, service_class)(**fields),
               "{} with {} idle connections to {}".format(service, IDLE_CONNECTIONS, node))


@pytest.mark.parametrize("node", NODES)
def test_a_new_subscriber_is_answered_while_idle_connections_are_open(graph, node):
    with idle_connections(graph[node]) as address:
        header = within(ANSWER_WITHIN_S, lambda: subscribe_handshake(address),
                        "a /rosout subscriber's handshake with {} idle connections to {}".format(IDLE_CONNECTIONS,
                                                                                                 node))
    assert "error" not in header and header["type"] == "rosgraph_msgs/Log", header
