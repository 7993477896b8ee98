"""Two hosts: network namespaces joined by a veth pair stand for two machines. Host A runs roscore and tb3_sim,
host B the Week 4 servers; service calls made on A move the robot as on one machine. The setup is the one the
README documents for two real machines (ROS_MASTER_URI pointing at A, ROS_IP on each)."""
import os
import subprocess
import uuid

import pytest

from roslab import RosProcess, wait_until

SUBNET = "10.231.{}.{}"


def ip(*args):
    return subprocess.run(["ip", *args], stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)


class Host:
    """One network namespace with a veth end at `address`; runs ROS commands with ROS_IP set to it."""

    def __init__(self, name, address, master_uri, workdir):
        self.name, self.address, self.workdir = name, address, workdir
        self.env = dict(os.environ, ROS_MASTER_URI=master_uri, ROS_IP=address, ROS_HOME=str(workdir),
                        ROS_LOG_DIR=str(workdir / "log"), PYTHONUNBUFFERED="1")
        self.env.pop("ROS_HOSTNAME", None)
        self.processes = []

    def start(self, *command):
        label = "{}-{}-{}".format(self.name, len(self.processes), command[1])
        process = RosProcess(["ip", "netns", "exec", self.name, *command], self.env,
                             self.workdir / (label + ".log"))
        self.processes.append(process)
        return process

    def run(self, *command, timeout_s=120, check=True):
        """Run a command on this host; its output (asserting exit code 0 when `check`)."""
        result = subprocess.run(["ip", "netns", "exec", self.name, *command], env=self.env, text=True,
                                stdout=subprocess.PIPE, stderr=subprocess.STDOUT, timeout=timeout_s)
        assert not check or result.returncode == 0, result.stdout
        return result.stdout

    def wait_for_services(self, names, timeout_s=60):
        """Wait until `rosservice list`, run on this host, shows every one of `names`."""
        wait_until(lambda: set(names) <= set(self.run("rosservice", "list", check=False).split()), timeout_s,
                   "services {} seen from {}".format(names, self.name), interval_s=0.5)

    def odom_x(self):
        return float(self.run("rostopic", "echo", "-n", "1", "/odom/pose/pose/position/x").split()[0])


@pytest.fixture(scope="module")
def hosts(tmp_path_factory):
    tag = uuid.uuid4().hex[:6]
    names = ["laba_" + tag, "labb_" + tag]
    created = ip("netns", "add", names[0])
    if created.returncode != 0:
        pytest.skip("cannot create network namespaces here ({}): the two-host test needs root and iproute2"
                    .format(created.stdout.strip()))
    subnet = int(tag[:2], 16)
    addresses = [SUBNET.format(subnet, 1), SUBNET.format(subnet, 2)]
    try:
        ip("netns", "add", names[1])
        ip("link", "add", "veth" + tag + "a", "netns", names[0], "type", "veth", "peer", "name", "veth" + tag + "b",
           "netns", names[1])
        for name, address, end in zip(names, addresses, "ab"):
            ip("-n", name, "addr", "add", address + "/24", "dev", "veth" + tag + end)
            ip("-n", name, "link", "set", "veth" + tag + end, "up")
            ip("-n", name, "link", "set", "lo", "up")
        master_uri = "http://{}:11311".format(addresses[0])
        robot = Host(names[0], addresses[0], master_uri, tmp_path_factory.mktemp("host_a"))
        servers = Host(names[1], addresses[1], master_uri, tmp_path_factory.mktemp("host_b"))
        yield robot, servers
    finally:
        for name in names:
            ip("netns", "del", name)


@pytest.fixture(scope="module")
def graph(hosts):
    robot, servers = hosts
    try:
        robot.start("roscore", "-p", "11311")
        robot.wait_for_services(["/rosout/get_loggers"])
        robot.start("roslaunch", "tb3_sim", "tb3_sim.launch", "world:=approach_arena", "gui:=false",
                    "real_time_factor:=2")
        wait_until(lambda: robot.run("rosparam", "get", "/use_sim_time", check=False).strip() == "true", 60,
                   "/use_sim_time before the servers start (rospy reads it once)", interval_s=0.5)
        servers.start("rosrun", "week4_services", "move_server.py")
        servers.start("rosrun", "week4_services", "approach_server.py")
        robot.wait_for_services(["/move_service", "/approach_service", "/gazebo/reset_world"])
        yield robot, servers
    finally:
        for process in reversed(servers.processes + robot.processes):
            process.stop()


def test_servers_run_on_the_other_host(graph):
    robot, servers = graph
    info = robot.run("rosnode", "info", "/move_service_server")
    assert "contacting node http://{}:".format(servers.address) in info


def test_move_service_called_on_the_robot_host_moves_the_robot(graph):
    robot, _ = graph
    before = robot.odom_x()
    reply = robot.run("rosservice", "call", "/move_service", "request_signal: true")
    assert "response_signal: True" in reply
    assert robot.odom_x() - before == pytest.approx(0.5, abs=0.03)


def test_approach_service_across_hosts(graph):
    robot, _ = graph
    robot.run("rosservice", "call", "/gazebo/reset_world")
    reply = robot.run("rosservice", "call", "/approach_service",
                      "{approach_distance: 0.4, approach_velocity: 0.15}")
    distance = float(reply.split(" is ")[1].split(" m")[0])
    assert distance == pytest.approx(0.4, abs=0.03), reply
