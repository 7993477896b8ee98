"""A private ROS master (roscore, so /rosout runs too) on a free port, for one test module.

Never the user's 11311: the port comes from the kernel. The environment for child processes points at this
master, binds to localhost and keeps ROS logs in a temporary folder.
"""
import contextlib
import os
import socket

import rosgraph

from roslab.processes import RosProcess
from roslab.waiting import wait_until


def free_port():
    """A TCP port on localhost that was free a moment ago."""
    with socket.socket(socket.AF_INET, socket.SOCK_STREAM) as sock:
        sock.bind(("localhost", 0))
        return sock.getsockname()[1]


class RosMaster:
    """roscore on a free port. `env` is the environment every process of this test must run with."""

    def __init__(self, workdir):
        self.port = free_port()
        self.uri = "http://localhost:{}".format(self.port)
        self.workdir = workdir
        self.env = dict(os.environ, ROS_MASTER_URI=self.uri, ROS_HOSTNAME="localhost",
                        ROS_HOME=str(workdir), ROS_LOG_DIR=str(workdir / "log"), PYTHONUNBUFFERED="1")
        self.env.pop("ROS_IP", None)
        self._processes = []
        self.core = self.start(["roscore", "-p", str(self.port)], "roscore")
        wait_until(self._rosout_ready, 30, "roscore on port {}".format(self.port))

    def _rosout_ready(self):
        try:
            return rosgraph.Master("/roslab_test", master_uri=self.uri).lookupNode("/rosout")
        except (rosgraph.MasterError, OSError):
            return None

    def restart_core(self):
        """Stop roscore (master and rosout) and start a fresh one on the same port, as a user who pressed
        Ctrl-C in the roscore terminal and started it again would."""
        self.core.stop()
        self.core = self.start(["roscore", "-p", str(self.port)], "roscore")
        wait_until(self._rosout_ready, 30, "the restarted roscore on port {}".format(self.port))

    def start(self, command, label):
        """Start `command` against this master; it is ended by `shutdown()` at the latest."""
        log_path = self.workdir / "{}-{}.log".format(len(self._processes), label)
        process = RosProcess(command, self.env, log_path)
        self._processes.append(process)
        return process

    def rosrun(self, package, executable, *args):
        return self.start(["rosrun", package, executable, *args], executable)

    def probe(self):
        """A TopicProbe node on this master, ended by `shutdown()`."""
        from roslab.probe import TopicProbe
        probe = TopicProbe(self)
        self._processes.append(probe)
        return probe

    def roslaunch(self, package, launch_file, *args):
        return self.start(["roslaunch", "--wait", package, launch_file, *args], launch_file)

    def shutdown(self):
        """End every process this master started (nodes and probes first, roscore last)."""
        for process in reversed(self._processes):
            process.stop()


@contextlib.contextmanager
def private_master(workdir):
    """A RosMaster in `workdir` that this process's own rospy calls (ServiceProxy needs no init_node) reach through
    ROS_MASTER_URI and ROS_HOSTNAME until the block ends; then its processes are ended and the variables restored."""
    saved = {name: os.environ.get(name) for name in ("ROS_MASTER_URI", "ROS_HOSTNAME")}
    master = RosMaster(workdir)
    os.environ.update(ROS_MASTER_URI=master.uri, ROS_HOSTNAME="localhost")
    try:
        yield master
    finally:
        master.shutdown()
        for name, value in saved.items():
            if value is None:
                os.environ.pop(name, None)
            else:
                os.environ[name] = value
