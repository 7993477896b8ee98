"""The fuzzed graph of the course's service servers (test_fuzz_services.py, test_fuzz_approach.py): one tb3_sim in
the approach arena at REAL_TIME_FACTOR, with the Week 4 servers (WEEK4_DEMO) or the simulator alone (APPROACH_ARENA),
and whichever other servers a module fuzzes.

The fuzz runs at REAL_TIME_FACTOR; a module's last check, that a server still does a valid motion right, is
judged on where the robot stopped, at JUDGING_FACTOR (Graph.paced). A stop that comes late by some wall time
overshoots by that time times the factor: a 43 ms stall of a busy 2-core machine, seen twice in fresh-clone runs
when the fuzz ran at 10x, was 0.43 s of sim time there, beyond the checks' 0.3-0.4 s; at REAL_TIME_FACTOR (5x) it
would be 0.22 s, with little margin left; at 2x it is 0.09 s. Gazebo itself runs the course at 1x, so the checks
stay stricter than the course's own setup."""
import contextlib
from typing import Dict, NamedTuple, Tuple

import rospy
from gazebo_msgs.srv import GetPhysicsProperties, GetWorldProperties, SetPhysicsProperties
from hypothesis import strategies as st
from std_srvs.srv import Empty

from roslab import wait_for_param, wait_for_service, wait_for_topic
from roslab.fuzz import MIN_REQUESTS, GraphWatch
from roslab.fuzz_strategies import float64s
from roslab.launch_args import CHEAP_CAMERA
from roslab.robot_view import RobotView, front_distance, pose_of

# Why not faster: each node on /use_sim_time takes every /clock message (100 per sim second), and on these machines
# a message handed to a process costs about 80 us of CPU whatever its language. With 12 nodes, 10x made the module
# CPU-bound on the clock alone: 92 s and 164 CPU s for test_fuzz_services run alone, 74 s and 113 CPU s at 5x.
REAL_TIME_FACTOR = 5
JUDGING_FACTOR = 2
MAX_LINEAR_MPS = 0.26
# (package, executable, node, service, extra arguments)
STOP_SERVER = ("course_sim_services", "moving_stop_services.py", "/moving_stop_services", "/stop", ())
APPROACH_SERVER = ("week4_services", "approach_server.py", "/approach_service_server", "/approach_service", ())


class Launch(NamedTuple):
    """`roslaunch package launch_file *args` and the {node: service} it starts."""

    package: str
    launch_file: str
    args: Tuple[str, ...]
    services: Dict[str, str]


SIMULATOR = {"/gazebo": "/gazebo/reset_world"}
# week4_demo.launch: the simulator in the approach arena and the three Week 4 servers.
WEEK4_DEMO = Launch("week4_services", "week4_demo.launch", (), dict(
    SIMULATOR, **{"/move_service_server": "/move_service", "/timed_move_service_server": "/timed_move_service",
                  "/approach_service_server": "/approach_service"}))
# The same simulator and world without the Week 4 servers, for a module that fuzzes one of them (by rosrun): each
# idle rospy node on /use_sim_time takes 5 % of a core at REAL_TIME_FACTOR receiving /clock.
APPROACH_ARENA = Launch("tb3_sim", "tb3_sim.launch", ("world:=approach_arena",), SIMULATOR)


class Graph:
    """tb3_sim from `launch` (with the Week 4 servers by default), the course's /moving and /stop (needed to reset
    the robot) and `servers` by rosrun, a RobotView."""

    def __init__(self, ros_master, servers=(), launch=WEEK4_DEMO):
        servers = [STOP_SERVER, *servers]
        processes = [ros_master.roslaunch(launch.package, launch.launch_file, *launch.args, "gui:=false",
                                          "real_time_factor:={}".format(REAL_TIME_FACTOR), *CHEAP_CAMERA)]
        wait_for_param(ros_master.uri, "/use_sim_time")   # before the rosrun servers read it
        processes += [ros_master.rosrun(package, executable, *args) for package, executable, _, _, args in servers]
        services = list(launch.services.values()) + [service for *_, service, _ in servers] + ["/moving"]
        for service in services:
            wait_for_service(ros_master.uri, service, timeout_s=60)
        wait_for_topic(ros_master.uri, "/scan")
        self.probe = RobotView(ros_master.probe()).probe
        nodes = list(launch.services) + [node for _, _, node, _, _ in servers]
        self.watch = GraphWatch(ros_master.uri, nodes, services, processes)

    def reset(self):
        """The robot stopped and back at the origin facing the box, with a LiDAR sweep taken there."""
        rospy.ServiceProxy("/stop", Empty)()
        rospy.ServiceProxy("/gazebo/reset_world", Empty)()
        self.fresh("/scan")

    def fresh(self, topic, predicate=lambda msg: True, delay_s=0.0):
        """The first message on `topic` stamped at least `delay_s` sim seconds after now that satisfies
        `predicate`. Stamps, not arrival order, say what is new: at REAL_TIME_FACTOR the probe may be
        behind the simulator by a few sim seconds."""
        after_s = self.sim_time() + delay_s
        return self.probe.wait_for_message(
            topic, predicate=lambda msg: msg["header"]["stamp"] >= after_s and predicate(msg), interval_s=0.02)

    @contextlib.contextmanager
    def paced(self, factor):
        """The simulator at real-time `factor` inside the block, set as in Gazebo (max_update_rate = factor /
        time_step through /gazebo/set_physics_properties), and back to what it was afterwards."""
        initial = rospy.ServiceProxy("/gazebo/get_physics_properties", GetPhysicsProperties)()
        set_physics = rospy.ServiceProxy("/gazebo/set_physics_properties", SetPhysicsProperties)

        def pace(max_update_rate):
            reply = set_physics(time_step=initial.time_step, max_update_rate=max_update_rate,
                                gravity=initial.gravity, ode_config=initial.ode_config)
            assert reply.success, reply.status_message

        pace(factor / initial.time_step)
        try:
            yield
        finally:
            pace(initial.max_update_rate)

    @contextlib.contextmanager
    def paused(self):
        """Physics paused inside the block (/gazebo/pause_physics), for fuzzing a service whose replies do not
        depend on the simulator running: /clock stops, so the dozen nodes on /use_sim_time (and the probe on /odom
        and /scan) idle. Measured with the graph of test_fuzz_services idle at load 8-12: 0.05 CPU s per wall
        second paused, 0.9-1.0 at REAL_TIME_FACTOR, 0.5 even at 1x. A server that reads the latest /scan keeps
        it; one that refuses an old camera image (the fruit detector) or stale /odom (the Week 4 servers) must
        not be fuzzed paused."""
        rospy.ServiceProxy("/gazebo/pause_physics", Empty)()
        try:
            yield
        finally:
            rospy.ServiceProxy("/gazebo/unpause_physics", Empty)()

    def sim_time(self):
        return rospy.ServiceProxy("/gazebo/get_world_properties", GetWorldProperties)().sim_time

    def pose(self):
        return pose_of(self.fresh("/odom"))

    def settled_pose(self):
        """The pose once /odom reports the robot has stopped."""
        def still(odom):
            twist = odom["twist"]["twist"]
            return abs(twist["linear"]["x"]) < 1e-3 and abs(twist["angular"]["z"]) < 1e-3
        return pose_of(self.fresh("/odom", still))

    def velocity(self):
        """(linear, angular) from /odom 2 s of sim time from now, once the wheels have ramped."""
        twist = self.fresh("/odom", delay_s=2.0)["twist"]["twist"]
        return twist["linear"]["x"], twist["angular"]["z"]

    def front_distance(self):
        return front_distance(self.fresh("/scan"))


@contextlib.contextmanager
def running_graph(ros_master, servers=(), launch=WEEK4_DEMO):
    """A Graph for a test module: every node must still be alive when the module is done (the module's master
    ends them all afterwards)."""
    graph = Graph(ros_master, servers, launch)
    yield graph
    graph.watch.assert_alive()


@contextlib.contextmanager
def reset_around(graph):
    """The graph for one test: the robot reset before and after, every node alive after."""
    graph.reset()
    yield graph
    graph.watch.assert_alive()
    graph.reset()


def speeds(limit):
    """float64 speeds: anything, or a valid one in (0, limit]."""
    return st.one_of(float64s(), st.floats(0.05, limit))


def report(fuzzer):
    print("fuzzed {}: {} requests".format(fuzzer.name, fuzzer.calls))
    assert fuzzer.calls >= MIN_REQUESTS
