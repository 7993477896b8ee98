"""A private ROS master (what roscore starts: rosmaster and /rosout) on a free port, for one test module.

Never the user's 11311: the port comes from the kernel. The environment for child processes points at this
master, binds to localhost and keeps ROS logs in a temporary folder.

The core is started as roscore's roslaunch starts it, without the roslaunch: `rosmaster --core -p PORT -w 3`,
then the parameters roscore.xml sets (/rosversion, /rosdistro) and roslaunch's /run_id with its log folder, then
the rosout node. That is the same master and the same rosout, but it costs 0.6 CPU seconds and is ready in
0.3 s, where roscore costs 1.5 CPU seconds and is ready in about 1 s (roslaunch's start-up, and the two
`rosversion` runs roscore.xml asks for). Every test module starts a master, so this is a few minutes of CPU per
suite. What roslaunch adds besides (respawning a rosout that dies) no test relies on; a test that types
`roscore` into a terminal gets the real one.
"""
import contextlib
import functools
import os
import subprocess
import uuid
from pathlib import Path

import rosgraph
import rospkg
from roslib.packages import find_node

from roslab.ports import free_port
from roslab.processes import RosProcess, stop_together
from roslab.waiting import wait_until

ROSMASTER_WORKERS = 3   # roslaunch's NUM_WORKERS, what roscore gives rosmaster
_ROSPACK = rospkg.RosPack()   # keeps the package crawl between lookups


def node_path(package, executable):
    """The file `rosrun package executable` runs, found as roslaunch finds a node's (roslib.packages.find_node).

    rosrun itself is a shell script that runs catkin_find twice (once for a --debug line it builds even without
    --debug), 0.4 CPU seconds per start, more than many nodes cost: in test_services_unit, 17 % of the module's CPU.
    Tests of the `rosrun` command itself run it."""
    found = find_node(package, executable, rospack=_ROSPACK)
    if len(found) == 2:   # catkin's devel-space relay (lib/<package>/) and the script it runs: rosrun runs the relay
        found = [path for path in found if Path(path).parent.parts[-2:] == ("lib", package)] or found
    if len(found) != 1:
        raise FileNotFoundError("rosrun {} {}: {} executables found, not one: {}".format(
            package, executable, len(found), found))
    return found[0]


@functools.lru_cache(maxsize=None)
def core_parameters():
    """/rosversion and /rosdistro as roscore.xml sets them (`rosversion roslaunch`, `rosversion -d`)."""
    def output(*command):
        return subprocess.run(command, stdout=subprocess.PIPE, text=True, check=True).stdout.strip()
    return {"/rosversion": output("rosversion", "roslaunch"), "/rosdistro": output("rosversion", "-d")}


class RosMaster:
    """rosmaster and /rosout on a free port. `env` is the environment every process of this test must run with;
    `core` lists the core's processes."""

    def __init__(self, workdir):
        self.port = free_port()
        self.uri = "http://localhost:{}".format(self.port)
        self.workdir = workdir
        self.env = dict(os.environ, ROS_MASTER_URI=self.uri, ROS_HOSTNAME="localhost",
                        ROS_HOME=str(workdir), ROS_LOG_DIR=str(workdir / "log"), PYTHONUNBUFFERED="1")
        self.env.pop("ROS_IP", None)
        self._processes = []
        self.core = []   # until the core has started: shutdown() then ends whatever did start, side by side
        try:
            self.core = self._start_core()
        except BaseException:   # Ctrl-C or a timeout while the core starts: nothing may outlive the test
            self.shutdown()
            raise

    def _start_core(self):
        """rosmaster, roscore's parameters and /run_id, then rosout; returns once /rosout is registered."""
        master = self.start(["rosmaster", "--core", "-p", str(self.port), "-w", str(ROSMASTER_WORKERS)],
                            "rosmaster")
        api = rosgraph.Master("/roslaunch", master_uri=self.uri)
        wait_until(lambda: self._answers(api.getPid), 30, "rosmaster on port {}".format(self.port))
        run_id = str(uuid.uuid1())
        (self.workdir / "log" / run_id).mkdir(parents=True, exist_ok=True)
        for name, value in dict(core_parameters(), **{"/run_id": run_id}).items():
            api.setParam(name, value)
        rosout = self.start([node_path("rosout", "rosout"), "__name:=rosout",
                             "__log:={}".format(self.workdir / "log" / run_id / "rosout-1.log")], "rosout")
        wait_until(lambda: self._answers(lambda: api.lookupNode("/rosout")), 30,
                   "rosout on port {}".format(self.port))
        return [master, rosout]

    @staticmethod
    def _answers(ask):
        try:
            return ask()
        except (rosgraph.MasterError, OSError):
            return None

    def restart_core(self):
        """Stop the core (rosout, then the master) and start a fresh one on the same port, as a user who pressed
        Ctrl-C in the roscore terminal and started it again would: the new master knows no node, topic or
        parameter but roscore's own."""
        for process in reversed(self.core):
            process.stop()
        self.core = self._start_core()

    def start(self, command, label):
        """Start `command` against this master; it is ended by `shutdown()` at the latest."""
        log_path = self.workdir / "{}-{}.log".format(len(self._processes), label)
        process = RosProcess(command, self.env, log_path)
        self._processes.append(process)
        return process

    def rosrun(self, package, executable, *args):
        """`rosrun package executable args`, without rosrun's package search each time (see node_path)."""
        return self.start([node_path(package, executable), *args], executable)

    def probe(self):
        """A TopicProbe node on this master, ended by `shutdown()`."""
        from roslab.probe import TopicProbe
        probe = TopicProbe(self)
        self._processes.append(probe)
        return probe

    def roslaunch(self, package, launch_file, *args):
        return self.start(["roslaunch", "--wait", package, launch_file, *args], launch_file)

    def shutdown(self):
        """End every process this master started: the nodes, launch files and probes side by side, then roscore's
        rosout and rosmaster, which the others need while they unregister."""
        stop_together(process for process in reversed(self._processes) if process not in self.core)
        for process in reversed(self.core):
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
