"""Fuzzing the Week 4 /approach_service (issue 8, item 1) in a graph of its own (fuzz_graph.py: tb3_sim in the
approach arena at REAL_TIME_FACTOR, the approach server and the course's /stop; no other server, so no camera
either, and not the other two Week 4 servers, which would only take /clock): a valid request drives to the box or
does not move when already close, any other one is refused with "Request failed: <field> ...", and an absurdly slow
one gives up at the server's time limit. Valid approaches in the fuzz are fast ones from the spawn pose; the slow
one has its own test. Afterwards every node is the same process, still offers its services and printed no traceback.

The fuzz's last approach is judged on its stopping distance, at JUDGING_FACTOR: how far a late stop overshoots
grows with the factor (fuzz_graph.py)."""
import math

import numpy
import pytest
import rospy
from hypothesis import given
from hypothesis import strategies as st
from tuos_msgs.srv import Approach

from roslab.fuzz import FUZZ_SETTINGS, ServiceFuzzer
from roslab.fuzz_strategies import float32s

from .fuzz_graph import (
    APPROACH_ARENA,
    APPROACH_SERVER,
    JUDGING_FACTOR,
    MAX_LINEAR_MPS,
    report,
    reset_around,
    running_graph,
    speeds,
)

APPROACH_DISTANCES_M = (0.2, 3.5)        # [min, max)
FAST_APPROACH_MPS = 0.2                  # valid approaches in the fuzz are at least this fast
SAFETY_TRAVEL_M, STILL_TIMEOUT_S = 3.5, 2.0
APPROACH_TIME_LIMIT_S = 60               # approach_server.py gives up after this much sim time


@pytest.fixture(scope="module")
def graph(ros_master):
    with running_graph(ros_master, [APPROACH_SERVER], APPROACH_ARENA) as graph:
        yield graph


@pytest.fixture
def robot(graph):
    with reset_around(graph) as robot:
        yield robot


def valid_approach(distance, velocity):
    return (math.isfinite(distance) and APPROACH_DISTANCES_M[0] <= distance < APPROACH_DISTANCES_M[1]
            and math.isfinite(velocity) and 0.0 < velocity <= MAX_LINEAR_MPS)


def approaches():
    """(approach_distance float32, approach_velocity float64): anything, minus valid slow approaches."""
    shortest, longest = (float(numpy.float32(limit)) for limit in APPROACH_DISTANCES_M)
    distances = st.one_of(float32s(), st.floats(shortest, longest, width=32, exclude_max=True))
    return st.tuples(distances, speeds(MAX_LINEAR_MPS)).filter(
        lambda request: not valid_approach(*request) or request[1] >= FAST_APPROACH_MPS)


def test_approach_service_fuzzed(robot):
    """A valid request drives to the box (or does not move when already close); any other one is refused
    with "Request failed: <field> ..."."""
    fuzzer = ServiceFuzzer("/approach_service", Approach)

    @FUZZ_SETTINGS
    @given(request=approaches())
    def approach(request):
        valid = valid_approach(*request)
        if valid:
            robot.reset()
        budget_s = SAFETY_TRAVEL_M / request[1] + STILL_TIMEOUT_S if valid else 0.0
        message = fuzzer.call(*request, motion_s=budget_s).response.response_message
        assert message.startswith(("Stopped:", "Did not move:") if valid else "Request failed: approach_"), \
            (request, message)

    approach()
    report(fuzzer)
    robot.reset()
    with robot.paced(JUDGING_FACTOR):
        message = rospy.ServiceProxy("/approach_service", Approach)(0.4, 0.1).response_message
        assert message.startswith("Stopped:")
        assert robot.front_distance() == pytest.approx(0.4, abs=0.04)


def test_approach_at_a_crawl_stops_at_the_time_limit(robot):
    """A valid but absurd velocity (1 um/s: the 1.3 m to the box would take two weeks) must not hold the
    server: it gives up after APPROACH_TIME_LIMIT_S of sim time, stops, and says so."""
    fuzzer = ServiceFuzzer("/approach_service", Approach)
    reply = fuzzer.call(0.4, 1e-6, motion_s=APPROACH_TIME_LIMIT_S + STILL_TIMEOUT_S)
    assert reply.response.response_message.startswith(
        "Stopped after the {} s time limit: the closest object ahead is 1.".format(APPROACH_TIME_LIMIT_S))
    assert rospy.ServiceProxy("/approach_service", Approach)(3.0, 0.1).response_message.startswith(
        "Did not move")
