"""Fuzzing the course's service servers (issue 8, item 1): Week 4, the ROS 2 Services unit ports and the
beginner_tutorials services, all against one tb3_sim in the approach arena at REAL_TIME_FACTOR (fuzz_graph.py;
the Week 4 /approach_service has a graph of its own, test_fuzz_approach.py).

Each test sends at least MIN_REQUESTS generated requests to one service (see roslab.fuzz_strategies: NaN,
+-inf, the type's extremes, empty, huge and unicode strings, near-misses of the accepted words) and checks
each reply against the service's documentation: a valid request does what it says, an invalid one gets the
documented refusal (success False, a "Request failed" message, or a ServiceException with the reason). Every
call must answer within REPLY_BUDGET_S wall seconds plus, for a valid motion, its duration in sim time.

Valid motions are kept short so that the module runs in a few minutes on two cores: valid durations are 1-2 s
(the refusal path still gets the whole int32 range) and /move_service's 5 s drive is drawn about one time in
fifty. Afterwards every node is the same process, still offers its services, printed no traceback, and answers a
valid request correctly, measured on /odom and /scan where the request moves the robot (a timed motion's
distance at JUDGING_FACTOR, see fuzz_graph.py).

A service whose replies do not depend on the simulator running (a sum, the latest /scan, a /cmd_vel published)
is fuzzed with physics paused (Graph.paused): the graph then idles instead of spending most of a core on /clock.
"""
import math

import pytest
import rospy
from custom_interfaces.srv import Move, MyCustomServiceMessage, StringServiceMessage
from hypothesis import given
from hypothesis import strategies as st
from services_quiz_srv.srv import Turn
from std_srvs.srv import Empty
from std_srvs.srv import SetBool as StdSetBool
from tuos_msgs.srv import SetBool, TimedMovement

from beginner_tutorials.srv import add_two_int, gazebo_server
from roslab.fuzz import FUZZ_SETTINGS, ServiceFuzzer
from roslab.fuzz_strategies import signed_ints, texts

from .fuzz_graph import JUDGING_FACTOR, MAX_LINEAR_MPS, report, reset_around, running_graph, speeds

INT64 = (-2 ** 63, 2 ** 63 - 1)
MAX_ANGULAR_RADPS, MAX_MOTION_S = 1.82, 60
STOP_LATENCY_SIM_S = 0.3                 # 150 ms of wall-clock latency in stopping at JUDGING_FACTOR (2x)
SERVERS = [  # (package, executable, node, service, extra arguments), besides the Week 4 servers and /stop
    ("exercise42_pkg", "moving_right_server.py", "/moving_right_server", "/moving_right", ()),
    ("movement_pkg", "movement_server.py", "/movement_server", "/movement", ()),
    ("movement_pkg", "move_server.py", "/move_server", "/move", ()),
    ("services_quiz", "turn_server.py", "/turn_server", "/turn", ()),
    ("fruit_detector_pkg", "detect_fruit_node.py", "/detect_fruit_node", "/detect_fruit_service", ()),
    ("beginner_tutorials", "add_two_int_server.py", "/add_two_int_server", "/add_two_int", ()),
    ("beginner_tutorials", "add_two_int_server_cpp", "/add_two_int_server_cpp", "/cpp/add_two_int",
     ("add_two_int:=/cpp/add_two_int",)),
    ("beginner_tutorials", "scan_server.py", "/scan_server", "/my_service", ()),
]


@pytest.fixture(scope="module")
def graph(ros_master):
    with running_graph(ros_master, SERVERS) as graph:
        yield graph


@pytest.fixture
def robot(graph):
    with reset_around(graph) as robot:
        yield robot


def durations(valid_max_s=2):
    """int32 seconds: anything outside 1..MAX_MOTION_S, or a short valid 1..valid_max_s."""
    return st.one_of(signed_ints(32).filter(lambda s: not 1 <= s <= MAX_MOTION_S), st.integers(1, valid_max_s))


def rare_true():
    """True about one time in fifty (hypothesis draws index-uniformly, derandomized)."""
    return st.sampled_from([False] * 25 + [True] + [False] * 24)


def overshoot(speed):
    """Tolerance of a timed motion at `speed` (m/s or rad/s): the stop command's latency, plus 1 cm."""
    return speed * STOP_LATENCY_SIM_S + 0.01


def distance_moved(before, after):
    return math.hypot(after[0] - before[0], after[1] - before[1])


# --- Week 4 ----------------------------------------------------------------------------------------------

def test_move_service_fuzzed(robot):
    """false: refused at once with a hint; true: drives for 5 s and says so."""
    fuzzer = ServiceFuzzer("/move_service", SetBool)

    @FUZZ_SETTINGS
    @given(signals=st.lists(rare_true(), min_size=1, max_size=3))
    def move(signals):
        for request_signal in signals:
            response = fuzzer.call(request_signal, motion_s=5.0 if request_signal else 0.0).response
            assert response.response_signal is request_signal, response.response_message
            assert ("Request complete" if request_signal else "request_signal to 'true'") in response.response_message

    move()
    report(fuzzer)
    robot.reset()
    before = robot.pose()
    with robot.paced(JUDGING_FACTOR):
        assert rospy.ServiceProxy("/move_service", SetBool)(True).response_signal is True
        assert distance_moved(before, robot.settled_pose()) == pytest.approx(0.5, abs=overshoot(0.1))


def test_timed_move_service_fuzzed(robot):
    """True exactly for fwd/back/left/right (any case, surrounding spaces) and 1..60 s."""
    fuzzer = ServiceFuzzer("/timed_move_service", TimedMovement)

    @FUZZ_SETTINGS
    @given(word=texts(["fwd", "back", "left", "right"]), duration=durations())
    def timed_move(word, duration):
        valid = word.strip().lower() in ("fwd", "back", "left", "right") and 1 <= duration <= MAX_MOTION_S
        reply = fuzzer.call(word, duration, motion_s=duration if valid else 0.0)
        assert reply.response.success is valid, (word, duration)

    timed_move()
    report(fuzzer)
    robot.reset()
    before = robot.pose()
    with robot.paced(JUDGING_FACTOR):
        assert rospy.ServiceProxy("/timed_move_service", TimedMovement)("fwd", 2).success is True
        assert robot.settled_pose()[0] - before[0] == pytest.approx(0.2, abs=overshoot(0.1))


# --- the ROS 2 Services unit ports -----------------------------------------------------------------------

def test_moving_right_fuzzed(robot):
    """data true: moving right with the course's reply; false: stopped with its reply."""
    fuzzer = ServiceFuzzer("/moving_right", StdSetBool)
    replies = {True: (True, "MOVING TO THE RIGHT RIGHT RIGHT!"), False: (False, "It is time to stop!")}

    @FUZZ_SETTINGS
    @given(signals=st.lists(st.booleans(), min_size=1, max_size=5))
    def moving_right(signals):
        for data in signals:
            response = fuzzer.call(data).response
            assert (response.success, response.message) == replies[data]

    with robot.paused():
        moving_right()
    report(fuzzer)
    robot.reset()
    assert rospy.ServiceProxy("/moving_right", StdSetBool)(True).success is True
    assert robot.velocity() == pytest.approx((0.3, -0.3), abs=0.01)
    rospy.ServiceProxy("/moving_right", StdSetBool)(False)
    assert robot.velocity() == pytest.approx((0.0, 0.0), abs=0.01)


def test_movement_fuzzed(robot):
    """success True for exactly "Turn Right", "Turn Left" and "Stop"."""
    fuzzer = ServiceFuzzer("/movement", MyCustomServiceMessage)
    words = ["Turn Right", "Turn Left", "Stop"]

    @FUZZ_SETTINGS
    @given(move=texts(words))
    def movement(move):
        assert fuzzer.call(move).response.success is (move in words), move

    with robot.paused():
        movement()
    report(fuzzer)
    robot.reset()
    assert rospy.ServiceProxy("/movement", MyCustomServiceMessage)("Turn Left").success is True
    assert robot.velocity() == pytest.approx((0.1, 0.5), abs=0.01)
    assert rospy.ServiceProxy("/movement", MyCustomServiceMessage)("Stop").success is True
    assert robot.velocity() == pytest.approx((0.0, 0.0), abs=0.01)


DIRECTION_LIMITS = {"forward": MAX_LINEAR_MPS, "backward": MAX_LINEAR_MPS, "left": MAX_ANGULAR_RADPS,
                    "right": MAX_ANGULAR_RADPS}


def test_move_fuzzed(robot):
    """"stop" always succeeds at once; a direction with a speed within its limit and 1..60 s succeeds after
    the motion; anything else is refused."""
    fuzzer = ServiceFuzzer("/move", Move)

    @FUZZ_SETTINGS
    @given(direction=texts(list(DIRECTION_LIMITS) + ["stop"]), velocity=speeds(MAX_ANGULAR_RADPS),
           seconds=durations())
    def move(direction, velocity, seconds):
        limit = DIRECTION_LIMITS.get(direction)
        drives = (limit is not None and math.isfinite(velocity) and 0 < velocity <= limit
                  and 1 <= seconds <= MAX_MOTION_S)
        reply = fuzzer.call(direction, velocity, seconds, motion_s=seconds if drives else 0.0)
        assert reply.response.success is (drives or direction == "stop"), (direction, velocity, seconds)

    move()
    report(fuzzer)
    robot.reset()
    before = robot.pose()
    with robot.paced(JUDGING_FACTOR):
        assert rospy.ServiceProxy("/move", Move)("forward", 0.2, 2).success is True
        assert robot.settled_pose()[0] - before[0] == pytest.approx(0.4, abs=overshoot(0.2))


def test_turn_fuzzed(robot):
    """left/right with (0, 1.82] rad/s and 1..60 s succeeds after the turn; anything else is refused."""
    fuzzer = ServiceFuzzer("/turn", Turn)

    @FUZZ_SETTINGS
    @given(direction=texts(["left", "right"]), velocity=speeds(MAX_ANGULAR_RADPS), seconds=durations())
    def turn(direction, velocity, seconds):
        turns = (direction in ("left", "right") and math.isfinite(velocity)
                 and 0 < velocity <= MAX_ANGULAR_RADPS and 1 <= seconds <= MAX_MOTION_S)
        reply = fuzzer.call(direction, velocity, seconds, motion_s=seconds if turns else 0.0)
        assert reply.response.success is turns, (direction, velocity, seconds)

    turn()
    report(fuzzer)
    robot.reset()
    before = robot.pose()
    with robot.paced(JUDGING_FACTOR):
        assert rospy.ServiceProxy("/turn", Turn)("left", 0.5, 2).success is True
        assert robot.settled_pose()[2] - before[2] == pytest.approx(1.0, abs=overshoot(0.5))


def test_detect_fruit_fuzzed(robot):
    """apple/banana (any case, padded) get an answer about the latest camera image (the approach arena holds
    nothing red or yellow: "no <fruit> in view"); any other word is refused with success False, naming the
    allowed words."""
    fuzzer = ServiceFuzzer("/detect_fruit_service", StringServiceMessage)

    @FUZZ_SETTINGS
    @given(word=texts(["apple", "banana"]))
    def detect(word):
        response = fuzzer.call(word).response
        fruit = word.strip().lower()
        if fruit in ("apple", "banana"):
            expected = "no {} in view".format(fruit)
        else:
            expected = "unknown fruit '{}': detect must be apple or banana".format(word)
        assert response.success is False and response.message == expected, (word, response.message)

    detect()
    report(fuzzer)


def test_moving_and_stop_fuzzed(robot):
    """Any sequence of the unit's /moving and /stop: each answers, and /stop then stops the robot. Hypothesis
    exhausts the sequences of 2 to 6 calls (124 of them, 320 calls to each service); up to 8 it made 1267 calls
    for the 400 needed, each a sequence of the same two stateless requests."""
    fuzzers = {name: ServiceFuzzer(name, Empty) for name in ["/moving", "/stop"]}

    @FUZZ_SETTINGS
    @given(sequence=st.lists(st.sampled_from(sorted(fuzzers)), min_size=2, max_size=6))
    def moving_and_stop(sequence):
        for name in sequence:
            assert fuzzers[name].call().error is None

    with robot.paused():
        moving_and_stop()
    for fuzzer in fuzzers.values():
        report(fuzzer)
    robot.reset()
    rospy.ServiceProxy("/moving", Empty)()
    assert robot.velocity() == pytest.approx((0.3, 0.3), abs=0.01)
    rospy.ServiceProxy("/stop", Empty)()
    assert robot.velocity() == pytest.approx((0.0, 0.0), abs=0.01)


# --- beginner_tutorials -----------------------------------------------------------------------------------

@pytest.mark.parametrize("service", ["/add_two_int", "/cpp/add_two_int"], ids=["python", "cpp"])
def test_add_two_int_fuzzed(graph, service):
    """The exact sum whenever it fits int64; otherwise an error naming the int64 range."""
    fuzzer = ServiceFuzzer(service, add_two_int)

    @FUZZ_SETTINGS
    @given(a=signed_ints(64), b=signed_ints(64))
    def add(a, b):
        reply = fuzzer.call(a, b)
        if INT64[0] <= a + b <= INT64[1]:
            assert reply.error is None and reply.response.sum == a + b, (a, b, reply)
        else:
            assert reply.error and "outside the int64 range" in reply.error, (a, b, reply)

    with graph.paused():
        add()
    report(fuzzer)
    graph.watch.assert_alive()
    assert rospy.ServiceProxy(service, add_two_int)(4, 5).sum == 9


def test_my_service_fuzzed(robot):
    """A direction 0..359 gives that LiDAR range; any other int64 an error naming 0 to 359."""
    fuzzer = ServiceFuzzer("/my_service", gazebo_server)

    @FUZZ_SETTINGS
    @given(direction=st.one_of(signed_ints(64), st.integers(0, 359)))
    def lookup(direction):
        reply = fuzzer.call(direction)
        if 0 <= direction <= 359:
            assert reply.error is None and not math.isnan(reply.response.distance), (direction, reply)
        else:
            assert reply.error and "direction must be an index from 0 to 359" in reply.error, (direction, reply)

    with robot.paused():
        lookup()
    report(fuzzer)
    robot.reset()
    box_face_m = 1.3 + 0.064   # the box's near face, seen from base_scan 6.4 cm behind base_footprint
    assert rospy.ServiceProxy("/my_service", gazebo_server)(0).distance == pytest.approx(box_face_m, abs=0.05)
    assert robot.pose()[0] == pytest.approx(0.0, abs=0.01)
