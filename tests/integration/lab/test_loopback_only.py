"""With scripts/env.sh's defaults, roscore and every node of the demo (plus a C++ node and turtlesim) listen
on loopback only: the listening sockets of every process this test started are checked with `ss -ltnp`."""
import re
import subprocess

import pytest

from roslab import wait_for_service, wait_for_topic

LOOPBACK_HOSTS = {"127.0.0.1", "[::1]", "::1"}
SS_USER = re.compile(r'\("(?P<name>[^"]+)",pid=(?P<pid>\d+),fd=\d+\)')


def with_descendants(pids):
    """`pids` and every process descended from them (roslaunch and roscore start their nodes as children)."""
    listing = subprocess.run(["ps", "-e", "-o", "pid=,ppid="], stdout=subprocess.PIPE, text=True).stdout
    parent_of = dict(tuple(map(int, line.split())) for line in listing.splitlines() if line.strip())
    found = set(pids)
    growing = True
    while growing:
        children = {pid for pid, parent in parent_of.items() if parent in found and pid not in found}
        found |= children
        growing = bool(children)
    return found


def listening_sockets():
    """[(local host, port, process name, pid)] for every listening TCP socket on this machine."""
    sockets = []
    for line in subprocess.run(["ss", "-ltnpH"], stdout=subprocess.PIPE, text=True).stdout.splitlines():
        fields = line.split()
        host, _, port = fields[3].rpartition(":")
        for user in SS_USER.finditer(line):
            sockets.append((host, int(port), user["name"], int(user["pid"])))
    return sockets


@pytest.fixture(scope="module")
def demo_processes(ros_master):
    started = [ros_master.roslaunch("week4_services", "week4_demo.launch", "gui:=false"),
               ros_master.rosrun("beginner_tutorials", "add_two_int_server_cpp"),
               ros_master.rosrun("turtlesim", "turtlesim_node", "_headless:=true")]
    for service in ["/approach_service", "/add_two_int", "/spawn", "/gazebo/reset_world"]:
        wait_for_service(ros_master.uri, service, timeout_s=60)
    wait_for_topic(ros_master.uri, "/scan")
    return with_descendants({process.pid for process in started + ros_master.core})


def test_every_listening_socket_is_on_loopback(demo_processes):
    ours = [socket for socket in listening_sockets() if socket[3] in demo_processes]
    names = {name for _, _, name, _ in ours}
    assert {"rosmaster", "rosout", "add_two_int_ser", "turtlesim_node"} <= names, names
    assert len(ours) >= 12, ours
    exposed = [socket for socket in ours if socket[0] not in LOOPBACK_HOSTS]
    assert not exposed, "listening on a non-loopback address: {}".format(exposed)
