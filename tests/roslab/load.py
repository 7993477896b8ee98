"""Service load for tests/integration/lab/test_load.py and tests/bench/load_bench.py: many clients calling one
service at once while tb3_sim runs at real time, and what the robot's topics did meanwhile.

`LoadGraph` starts tb3_sim (turtlebot3_world, real_time_factor 1) and the tutorial's add_two_int servers
(Python on /add_two_int, C++ on /cpp/add_two_int) on a RosMaster, with a probe on /odom and /scan.
`LoadGraph.hammer(LOADS[name])` runs CLIENTS threads of the calling process, each with its own persistent
rospy.ServiceProxy (no node needed), making CALLS calls each, all released together; it returns a LoadRun
with every call's latency, every failure, and the /odom and /scan rates over the load.
"""
import math
import statistics
import threading
import time
from typing import Callable, List, NamedTuple

import rospy
from gazebo_msgs.srv import GetModelState

from beginner_tutorials.srv import add_two_int
from roslab.waiting import wait_for_service

CLIENTS = 20
CALLS = 100
RATE_TOPICS = {"/odom": "nav_msgs/Odometry", "/scan": "sensor_msgs/LaserScan"}
EXPECTED_RATES_HZ = {"/odom": 30.0, "/scan": 5.0}
ROBOT = "turtlebot3_waffle"
ROBOT_SPAWN_XY = (-2.0, -0.5)
MIN_WINDOW_S = 2.0
"""Topic rates are measured over the load, or over MIN_WINDOW_S from its start when it was over sooner (a
fast server answers 2000 calls in under a second, too short a window to see a 5 Hz /scan in)."""


class Load(NamedTuple):
    """What the clients call: `request(client, call)` gives a call's arguments and `check(response, client,
    call)` returns None, or the text of what is wrong with the response."""

    service: str
    service_class: type
    request: Callable
    check: Callable


def _check_sum(response, client, call):
    expected = client * 1000 + call
    return None if response.sum == expected else "{} + {} gave {}".format(client * 1000, call, response.sum)


def _check_robot_state(response, client, call):
    if not response.success:
        return response.status_message
    position = response.pose.position
    if not all(math.isclose(got, spawn, abs_tol=0.01) for got, spawn in zip((position.x, position.y),
                                                                              ROBOT_SPAWN_XY)):
        return "the robot is reported at ({}, {})".format(position.x, position.y)
    return None


LOADS = {
    "add_two_int": Load("/add_two_int", add_two_int, lambda client, call: (client * 1000, call), _check_sum),
    "add_two_int_cpp": Load("/cpp/add_two_int", add_two_int, lambda client, call: (client * 1000, call),
                            _check_sum),
    "get_model_state": Load("/gazebo/get_model_state", GetModelState, lambda client, call: (ROBOT, ""),
                            _check_robot_state),
}
"""The loads of issue 8: the tutorial's add_two_int server (Python, and the C++ one for comparison) and
tb3_sim's most-called service."""


class LoadRun(NamedTuple):
    """One load: latencies (s) of the calls that succeeded, failures as text, the wall time it took, and per
    topic the rates of `topic_rates`."""

    latencies_s: List[float]
    failures: List[str]
    wall_s: float
    topics: dict

    def percentile_ms(self, percent):
        """The `percent`th percentile of the call latencies in milliseconds."""
        return 1000.0 * statistics.quantiles(self.latencies_s, n=100, method="inclusive")[percent - 1]


def topic_rates(entries):
    """What a list of probe entries (at least three messages) says about their topic: "stamps_hz", the rate
    in sim time from the header stamps; "largest_gap_s", the largest sim-time gap between two consecutive
    messages (a missing message shows up here); "real_time_factor", sim seconds of stamps per wall second of
    arrivals (1.0: the rate held in wall time too)."""
    stamps = [entry["msg"]["header"]["stamp"] for entry in entries]
    arrivals = [entry["wall"] for entry in entries]
    if len(stamps) < 3:
        raise AssertionError("only {} messages during the load".format(len(stamps)))
    return {"stamps_hz": (len(stamps) - 1) / (stamps[-1] - stamps[0]),
            "largest_gap_s": max(b - a for a, b in zip(stamps, stamps[1:])),
            "real_time_factor": (stamps[-1] - stamps[0]) / (arrivals[-1] - arrivals[0])}


class LoadGraph:
    """tb3_sim at real time and both add_two_int servers on `master`, and a probe on /odom and /scan."""

    def __init__(self, master):
        self.master = master
        master.roslaunch("tb3_sim", "tb3_sim.launch", "world:=turtlebot3_world", "gui:=false",
                         "real_time_factor:=1", "x_pos:={}".format(ROBOT_SPAWN_XY[0]),
                         "y_pos:={}".format(ROBOT_SPAWN_XY[1]))
        master.rosrun("beginner_tutorials", "add_two_int_server.py")
        master.rosrun("beginner_tutorials", "add_two_int_server_cpp", "add_two_int:=/cpp/add_two_int")
        for service in ["/gazebo/get_model_state", "/add_two_int", "/cpp/add_two_int"]:
            wait_for_service(master.uri, service, timeout_s=60)
        self.probe = master.probe()
        for topic, msg_type in RATE_TOPICS.items():
            self.probe.subscribe(topic, msg_type)
            self.probe.wait_for_message(topic)

    def hammer(self, load, clients=CLIENTS, calls=CALLS, timeout_s=300.0):
        """Run `load` (a Load) from `clients` threads making `calls` calls each; a client still busy after
        `timeout_s` counts as a failure."""
        start = threading.Barrier(clients + 1)
        latencies, failures, lock = [], [], threading.Lock()

        def client(index):
            proxy = rospy.ServiceProxy(load.service, load.service_class, persistent=True)
            start.wait()
            try:
                for call in range(calls):
                    began = time.monotonic()
                    try:
                        problem = load.check(proxy(*load.request(index, call)), index, call)
                    except (rospy.ServiceException, OSError) as error:
                        problem = "{}: {}".format(type(error).__name__, error)
                    latency = time.monotonic() - began
                    with lock:
                        if problem:
                            failures.append(problem)
                        else:
                            latencies.append(latency)
            finally:
                proxy.close()

        threads = [threading.Thread(target=client, args=(index,), daemon=True) for index in range(clients)]
        for thread in threads:
            thread.start()
        for topic in RATE_TOPICS:
            self.probe.take(topic)
        start.wait()
        began = time.monotonic()
        for thread in threads:
            thread.join(max(0.0, began + timeout_s - time.monotonic()))
        wall_s = time.monotonic() - began
        failures += ["a client was still calling after {:.0f} s".format(timeout_s)
                     for thread in threads if thread.is_alive()]
        time.sleep(max(0.0, MIN_WINDOW_S - wall_s))
        topics = {topic: topic_rates(self.probe.take(topic)) for topic in RATE_TOPICS}
        return LoadRun(latencies, failures, wall_s, topics)
