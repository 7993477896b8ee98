"""The grader's hands on the ROS graph during a check run: the only module of lab_grader.checks that imports rospy.

`GradingContext` is one rospy node (`/lab_grader_checks_<pid>...`, anonymous) in the graph of the simulator and
the student's nodes. It
- finds the services a suite expects the way a marker would (`find_services`): by the name the course asks for,
  if it has the expected md5sum; else any service on the master whose md5sum is the expected type's (a
  student's com2009_msgs/SetBool serves for tuos_msgs/SetBool). The md5sum and type come from the service's own
  TCPROS header (a probe, as `rosservice type` does), so a type the grader cannot import is still recognised;
- reads the robot through tb3_sim's private ground-truth channel (lab_grader.checks.ground_truth), never through
  /odom, /clock, /scan or /gazebo/reset_world, which any node on the master can forge, pause or serve itself: the
  simulator's sim time, the robot's true pose and speeds, a reset and a noise-free front distance;
- prepares the robot before each check (`prepare`): waits until the simulator is connected to every publisher
  of /cmd_vel (at most COMMANDS_HEARD_WALL_S: a node's first command, published before the simulator connected to
  it, would be lost; lab_grader.checks.command_links), zeroes /cmd_vel (tb3_sim holds the last command), resets
  through the channel, then waits until the robot is at rest (STILL_SAMPLES consecutive still samples stamped
  RESET_MARGIN_S or more after the reset, within `still_timeout_s` wall seconds) and until SENSORS_AFTER_RESET_S of
  sim time have passed since the reset: a node that keeps the latest /scan (the course's template does) must have
  had a sweep taken after the reset, as it has when a marker resets Gazebo and then types the call;
- makes one graded call (`observe`): records the true motion from before the call, calls the service on a daemon
  thread, waits for the reply for at most `timeout_s` seconds of SIM time (the simulator's, so the verdict does
  not depend on its real-time factor), keeps recording for `settle_s` of sim time after the reply, and, if asked,
  measures the front distance once still. A call with no reply in time is abandoned on its thread (a hung student
  callback cannot be interrupted from the client side; the daemon thread dies with the runner), and the
  observation says "no reply within N s of sim time";
- watches for interference from the reset before a check to the end of its recording (lab_grader.checks.
  interference): paused physics and /gazebo world changes (from the channel), and foreign publishers of the
  simulator's topics or an impostor under its node name (the master, polled every INTERFERENCE_POLL_WALL_S, and
  the messages of any other publisher of those topics). What was seen is reported in the observation; physics
  left paused ends the check when the clock has stalled (an interference verdict, not an error).

- finds the actionlib servers a suite expects (`find_actions`): by the course's namespace when its
  <ns>/result topic carries the expected <Name>ActionResult type, else any namespace whose result topic has a type
  of the same name in another package (com2009_msgs/counterActionResult for beginner_tutorials/counter). The
  master knows topic types by name only, so the name is what is compared; the client's md5sum check on
  connecting rejects a look-alike of another layout;
- sends one graded goal (`observe_action`): records every feedback message, cancels the goal `cancel_after_s`
  after sending it if asked, and waits at most `timeout_s` for it to end, all in ROS time; with a robot it also
  records the true motion from before the goal until `settle_s` after its end, the front distance once still if
  asked, and the interference meanwhile, as `observe` does for a call.

- records one run (`observe_run`): once the robot is prepared, it tells the grader to start the student's node
  (it creates the file `ready_path`, when set) and records the true motion and the interference from then until
  the run's duration after the robot first moved (in sim time), or its start_s (of sim and of wall time) without
  motion; once the grader says the node has ended by itself (the file `ended_path` exists) and the robot has rested
  for RESTED_AFTER_END_S, the recording ends there (nothing more can happen: the course's colour search exits after
  its last pillar).

Each wait above is lapped on `timeline` (lab_grader.checks.timeline) as it ends, for the runner's log: heard,
reset and rest (prepare), reply, tail and front (a call), client, result, tail and front (a goal), first motion and
recording (a run).

A suite without a world has no robot (`robot=False`): no /odom, /scan or /cmd_vel, nothing to reset, ROS time is
wall time, and observations carry no samples.

Sim-time waits are guarded in wall time: if the simulated clock does not advance for CLOCK_STALL_WALL_S wall
seconds (the simulator died), the wait ends with a CheckError instead of hanging the runner.
The robot is tb3_sim's single robot in the root namespace, driven on /cmd_vel.
"""
import math
import os
import re
import threading
import time
import xmlrpc.client
from typing import Dict, Sequence

import actionlib
import genpy
import rosgraph
import roslib.message
import rospy
import rosservice
from actionlib_msgs.msg import GoalStatus
from geometry_msgs.msg import Twist

from lab_grader.checks import command_links, image_folder, interference
from lab_grader.checks.action_checks import ActionObservation
from lab_grader.checks.ground_truth import TruthClient
from lab_grader.checks.motion import Observation, is_still
from lab_grader.checks.run_checks import RunObservation
from lab_grader.checks.timeline import Timeline
from lab_grader.checks.verdicts import CheckError, FoundService, InterferenceError, Interrupted
from lab_grader.suite_file import GOAL_STATES

NODE_NAME = "lab_grader_checks"
CMD_VEL_TOPIC = "/cmd_vel"
FIRST_SAMPLE_WALL_S = 30.0     # wait this long for the first ground-truth sample before giving up
CLOCK_STALL_WALL_S = 10.0      # sim time frozen this long during a sim-time wait: the simulator is gone
CMD_VEL_CONNECT_WALL_S = 5.0   # wait this long for the simulator to connect to our /cmd_vel publisher
COMMANDS_HEARD_WALL_S = 5.0    # ... and before a check, this long for it to connect to every /cmd_vel publisher
STILL_SAMPLES = 3              # consecutive still samples (0.1 s at 30 Hz) after a reset = at rest
RESET_MARGIN_S = 0.1           # only samples stamped this much sim time after the reset count as "after it"
SENSORS_AFTER_RESET_S = 0.3    # sim s after a reset before a check: one LiDAR period (5 Hz) for a sweep taken
                               # after it, 0.1 s for it to reach the student's node
INTERFERENCE_POLL_WALL_S = 0.2  # the master's publishers are looked at this often during a check
ACTION_CONNECT_WALL_S = 5.0    # an action client must connect to the server's topics within this
SERVER_ERROR_TEXT = "responded with an error"   # rospy's words for a server's error answer (its callback raised)
SERVER_ERROR_BYTES = re.compile(r"(responded with an error: )b(['\"])(.*)\2$", re.DOTALL)
POLL_WALL_S = 0.2              # service discovery polls the master this often
STATE_NAMES = {getattr(GoalStatus, name): name for name in GOAL_STATES}   # 3 -> "SUCCEEDED"
WAIT_SLICE_WALL_S = 0.01
RESTED_AFTER_END_S = 2.0       # a run ends early once its node has ended and the robot has rested this long (sim s)


def message_dict(message):
    """A ROS message's fields as plain data (nested messages as dicts, times as seconds, bytes as lists)."""
    if isinstance(message, genpy.Message):
        return {slot: message_dict(getattr(message, slot)) for slot in message.__slots__}
    if isinstance(message, (genpy.Time, genpy.Duration)):
        return message.to_sec()
    if isinstance(message, (list, tuple)):
        return [message_dict(item) for item in message]
    if isinstance(message, bytes):
        return list(message)
    return message


def _load_class(load, name, kind, type_name):
    """`load(name)` (a roslib loader), or CheckError naming the `kind` of type `type_name` that cannot be imported."""
    try:
        loaded = load(name)
    except (ValueError, ImportError) as error:
        raise CheckError("cannot load {} type {}: {}".format(kind, type_name, error)) from None
    if loaded is None:
        raise CheckError("cannot load {} type {}: is its package built?".format(kind, type_name))
    return loaded


def action_message_class(type_name, part):
    """The Python class <Name><part> ("Action", "Goal") of action type `type_name` (CheckError when it cannot be
    imported)."""
    return _load_class(roslib.message.get_message_class, type_name + part, "action", type_name)


def _wait_wall(deadline, done):
    """Polls `done()` until it is true or the wall-clock `deadline` (time.monotonic()) passes; returns done()."""
    while not done() and time.monotonic() < deadline:
        time.sleep(WAIT_SLICE_WALL_S)
    return done()


def service_class(type_name):
    """The Python class of service type `type_name` (CheckError when it cannot be imported)."""
    return _load_class(roslib.message.get_service_class, type_name, "service", type_name)


class _Call:
    """One service call on a daemon thread; `done` is set when it returned or raised, `replied_s` is `now()` then."""

    def __init__(self, proxy, request, now):
        self.reply = None
        self.error = None
        self.server_error = False
        self.replied_s = None
        self.done = threading.Event()
        self._now = now
        self._thread = threading.Thread(target=self._run, args=(proxy, request), daemon=True, name="graded-call")
        self._thread.start()

    def _run(self, proxy, request):
        try:
            self.reply = proxy.call(request)
        except Exception as error:  # noqa: BLE001 - whatever the student's server does becomes the verdict's text
            # rospy shows the server's error text as a bytes literal (responded with an error: b'...'): unwrap it
            text = SERVER_ERROR_BYTES.sub(r"\1\3", str(error))
            self.error = "the call failed: {}: {}".format(type(error).__name__, text)
            self.server_error = SERVER_ERROR_TEXT in text
        finally:
            self.replied_s = self._now()
            self.done.set()


class _InterferenceWatch:
    """The ROS side of interference during one check. Every INTERFERENCE_POLL_WALL_S it asks the master who
    publishes the guarded topics; a topic that gains a publisher other than the simulator is listened to (only
    then: subscribing to the simulator's lazy topics would make it compute them), and each message from another
    node than the simulator (its connection header's callerid) counts as published. It also notes an impostor: the
    simulator's node name registered with another XML-RPC URI than the one the private channel gave."""

    def __init__(self, simulator):
        self.simulator = simulator         # the channel's hello: {"node", "uri", "robot"}
        self.impostor = False
        self._heard = {}                   # topic -> nodes heard publishing it since restart()
        self._heard_lock = threading.Lock()
        self._listening = {}               # topic -> rospy.Subscriber
        self._polled = -math.inf

    def restart(self):
        with self._heard_lock:
            self._heard = {}
        self.impostor, self._polled = False, -math.inf

    @property
    def heard(self):
        with self._heard_lock:
            return {topic: set(nodes) for topic, nodes in self._heard.items()}

    def _on_message(self, message, topic):
        node = (getattr(message, "_connection_header", None) or {}).get("callerid")
        if node != self.simulator["node"]:
            with self._heard_lock:
                self._heard.setdefault(topic, set()).add(node or "(unnamed)")

    def poll(self, force=False):
        if not force and time.monotonic() - self._polled < INTERFERENCE_POLL_WALL_S:
            return
        self._polled = time.monotonic()
        master = rosgraph.Master(rospy.get_name())
        node = self.simulator["node"]
        try:
            publishers = master.getSystemState()[0]
            uri = master.lookupNode(node)
        except (rosgraph.MasterError, OSError):
            return     # the master is busy or the simulator's name is unregistered for a moment: look again later
        for topic in interference.foreign_publishers(publishers, node):
            if topic not in self._listening:
                self._listening[topic] = rospy.Subscriber(topic, rospy.AnyMsg, self._on_message, callback_args=topic,
                                                          queue_size=10)
        self.impostor = self.impostor or uri != self.simulator["uri"]


class _FeedbackRecorder:
    """Every message on an action's feedback topic, with the time it arrived, from a subscriber of its own.

    SimpleActionClient drops a feedback that arrives before its send_goal has stored the new goal handle, which a
    server that sends its first feedback as soon as the goal arrives can hit on a busy CPU: the student would lose
    a mark for actionlib's race. This subscriber is connected before any goal is sent and keeps everything; the
    goal's own messages are picked out by its goal id afterwards."""

    def __init__(self, action_name, feedback_class, now):
        self._now = now
        self._lock = threading.Lock()
        self._messages = []
        self._subscriber = rospy.Subscriber(action_name + "/feedback", feedback_class, self._on_message)

    def _on_message(self, message):
        arrived_s = self._now()
        with self._lock:
            self._messages.append((arrived_s, message))

    def connected(self):
        return self._subscriber.get_num_connections() > 0

    def unregister(self):
        self._subscriber.unregister()

    def of_goal(self, goal_id, sent_s):
        """[(s after the goal was sent, the feedback's fields)] of goal `goal_id`, in arrival order."""
        with self._lock:
            return [(arrived_s - sent_s, message_dict(message.feedback)) for arrived_s, message in self._messages
                    if message.status.goal_id.id == goal_id]


class GradingContext:
    """See the module docstring. Create it once per run (it calls rospy.init_node). With a robot, `ground_truth`
    is the path of tb3_sim's ground-truth socket (its ~ground_truth_socket). `student_home` is the HOME of the
    student's nodes, where their saved files are looked for (None: unknown)."""

    def __init__(self, robot=True, ground_truth=None, student_home=None):
        if robot and not ground_truth:
            raise CheckError("a suite with a world needs the simulator's ground-truth channel (--ground-truth)")
        rospy.init_node(NODE_NAME, anonymous=True)
        self.robot = robot
        self.student_home = student_home
        self._changed = threading.Condition()
        self._action_clients = {}         # action name -> (SimpleActionClient, _FeedbackRecorder), made once
        self._sim_seen = (None, time.monotonic())   # (last sim time seen, wall time it changed)
        self._window = None               # the ground-truth Mark of the current check's start (prepare)
        self.ready_path = None            # a run's node is started by the grader once this file exists
        self.ended_path = None            # the grader creates this file when a run's node has ended by itself
        self.timeline = Timeline()        # the current check's phases (lab_grader.checks.timeline), begun by the runner
        if not robot:
            return
        self._truth = TruthClient(ground_truth)
        self._watch = _InterferenceWatch(self._truth.identity)
        self._cmd_vel = rospy.Publisher(CMD_VEL_TOPIC, Twist, queue_size=1)

    # ---- time -----------------------------------------------------------------------------------------------------

    def now(self):
        """Sim time in seconds: the simulator's own (from the ground-truth channel); without a robot, rospy time."""
        return self._truth.now() if self.robot else rospy.get_rostime().to_sec()

    def _check_running(self):
        if rospy.is_shutdown():
            raise Interrupted("the runner was interrupted (rospy shut down)")

    def _check_clock(self):
        """CheckError when the sim clock has not advanced for CLOCK_STALL_WALL_S wall seconds (InterferenceError
        when the simulator says physics is paused)."""
        now, wall = self.now(), time.monotonic()
        seen, since = self._sim_seen
        if now != seen:
            self._sim_seen = (now, wall)
        elif wall - since > CLOCK_STALL_WALL_S:
            self._raise_if_interfered()
            raise CheckError("simulated time stopped at {:.2f} s for {:.0f} s of wall time: is the simulator "
                             "running?".format(now, CLOCK_STALL_WALL_S))

    def _check_interference(self):
        """During a check: let the watch poll the master."""
        if self.robot and self._window is not None:
            self._watch.poll()

    def _findings(self):
        """What interfered since the check's window opened, in words (lab_grader.checks.interference)."""
        if not self.robot or self._window is None:
            return []
        self._watch.poll(force=True)
        return interference.findings(self._truth.since(self._window), self._watch.heard, self._watch.impostor,
                                     self._watch.simulator["node"])

    def _raise_if_interfered(self):
        findings = self._findings()
        if findings:
            raise InterferenceError(findings)

    def _pause(self):
        """Wait one slice for news (ground truth, or anything else when there is no robot)."""
        if self.robot:
            self._truth.wait(WAIT_SLICE_WALL_S)
        else:
            with self._changed:
                self._changed.wait(WAIT_SLICE_WALL_S)

    def _wait_sim(self, until_s, done=lambda: False, at_least_wall_s=0.0):
        """Wait until `done()` (True) or sim time `until_s` (False), and for at least `at_least_wall_s` wall seconds
        unless done, watching for a stalled clock, interference and shutdown."""
        self._sim_seen = (None, time.monotonic())
        wall_until = time.monotonic() + at_least_wall_s
        while True:
            if done():
                return True
            if self.now() >= until_s and time.monotonic() >= wall_until:
                return False
            self._check_running()
            self._check_interference()
            self._check_clock()
            self._pause()

    def wait_until_ready(self):
        """Wait (wall, FIRST_SAMPLE_WALL_S) for the first ground-truth sample and for tb3_sim to subscribe
        /cmd_vel."""
        if not self.robot:
            return
        deadline = time.monotonic() + FIRST_SAMPLE_WALL_S
        while self._truth.latest is None:
            self._check_running()
            if time.monotonic() > deadline:
                raise CheckError("no ground-truth sample after {:.0f} s: is tb3_sim running with physics "
                                 "unpaused?".format(FIRST_SAMPLE_WALL_S))
            self._truth.wait(WAIT_SLICE_WALL_S)
        deadline = time.monotonic() + CMD_VEL_CONNECT_WALL_S
        while self._cmd_vel.get_num_connections() == 0 and time.monotonic() < deadline:
            self._check_running()
            time.sleep(WAIT_SLICE_WALL_S)

    # ---- services -------------------------------------------------------------------------------------------------

    def _services_on_master(self) -> Dict[str, str]:
        """{service name: rosrpc URI} of every service registered with the master."""
        master = rosgraph.Master(rospy.get_name())
        names = sorted(name for name, _providers in master.getSystemState()[2])
        uris = {}
        for name in names:
            try:
                uris[name] = master.lookupService(name)
            except (rosgraph.MasterError, OSError):
                continue    # it left the master meanwhile
        return uris

    @staticmethod
    def _service_header(name, uri, cache):
        """(type, md5sum) the server of `name` at `uri` declares in its TCPROS header, cached per (name, uri);
        (None, None) while it cannot be reached (it is looked at again at the next poll)."""
        key = (name, uri)
        if key not in cache:
            try:
                fields = rosservice.get_service_headers(name, uri)
            except Exception:  # noqa: BLE001 - unreachable, dead, or a malformed header: not a match this time
                return None, None
            cache[key] = (fields.get("type"), fields.get("md5sum"))
        return cache[key]

    def _discover(self, kind: str, specs: Sequence, by_type_grace_s: float, snapshot,
                  match) -> Dict[str, FoundService]:
        """The discovery loop shared by services and actions: poll `snapshot()` (the master's state) until every
        spec is decided or its wait_s has passed. `match(spec, state)` gives (the type if the course's name
        serves the expected type else None, why the course's name does not match or None, [(another name, its
        type)] of the expected type). The course's name wins at once; another name is taken `by_type_grace_s`
        after it appeared (the course's name may still come), or at the deadline. `kind` ("service", "action")
        words the note when nothing is found."""
        started = time.monotonic()
        type_seen_at = {}
        found = {}
        while True:
            now = time.monotonic()
            state = snapshot()
            for spec in specs:
                if spec.name in found:
                    continue
                named_type, wrong_name, candidates = match(spec, state)
                if named_type is not None:
                    found[spec.name] = FoundService(spec.name, spec.type, spec.name, "by name", named_type, None)
                    continue
                deadline_passed = now - started >= spec.wait_s
                if candidates:
                    type_seen_at.setdefault(spec.name, now)
                    if now - type_seen_at[spec.name] >= by_type_grace_s or deadline_passed:
                        (chosen, chosen_type), others = candidates[0], candidates[1:]
                        notes = [wrong_name] if wrong_name else []
                        if others:
                            notes.append("others of the same type: " + ", ".join(name for name, _ in others))
                        found[spec.name] = FoundService(spec.name, spec.type, chosen, "by type", chosen_type,
                                                        "; ".join(notes) or None)
                elif deadline_passed:
                    note = wrong_name or "no {} named {} and none of type {} after {:.0f} s".format(
                        kind, spec.name, spec.type, spec.wait_s)
                    found[spec.name] = FoundService(spec.name, spec.type, None, None, None, note)
            if len(found) == len(specs):
                return {spec.name: found[spec.name] for spec in specs}
            self._check_running()
            time.sleep(POLL_WALL_S)

    def find_services(self, specs: Sequence, by_type_grace_s: float) -> Dict[str, FoundService]:
        """Find every spec (suite_file.ServiceSpec) as described in the module docstring; waits up to each spec's
        wait_s wall seconds (all at once, from now). Returns {spec.name: FoundService}."""
        expected_md5 = {spec.name: service_class(spec.type)._md5sum for spec in specs}
        headers = {}        # (name, uri) -> (type, md5sum): a server's type does not change while it lives
        own = rospy.get_name() + "/"

        def snapshot():
            try:
                return self._services_on_master()
            except (rosgraph.MasterError, OSError) as error:
                raise CheckError("cannot list the master's services: {}".format(error)) from None

        def match(spec, on_master):
            def header_of(name):
                return self._service_header(name, on_master[name], headers)

            md5 = expected_md5[spec.name]
            named_type, named_md5 = header_of(spec.name) if spec.name in on_master else (None, None)
            if named_md5 == md5:
                return named_type, None, []
            wrong_name = None
            if named_type is not None:
                wrong_name = "{} is served with type {}, whose md5sum differs from {}'s".format(
                    spec.name, named_type, spec.type)
            candidates = [(name, header_of(name)[0]) for name in on_master
                          if name not in expected_md5 and not name.startswith(own) and header_of(name)[1] == md5]
            return None, wrong_name, candidates

        return self._discover("service", specs, by_type_grace_s, snapshot, match)

    def find_actions(self, specs: Sequence, by_type_grace_s: float) -> Dict[str, FoundService]:
        """Find every action spec (suite_file.ServiceSpec of `actions:`) by its <ns>/result topic, as described in
        the module docstring. Returns {spec.name: FoundService}, `found` being the action namespace. The action
        clients of an earlier lookup are let go first: their server may have been another exercise's node."""
        for client, recorder in self._action_clients.values():
            client.action_client.stop()
            recorder.unregister()
        self._action_clients.clear()
        expected = {spec.name: spec.type.split("/")[1] for spec in specs}

        def snapshot():
            try:
                topics = rosgraph.Master(rospy.get_name()).getPublishedTopics("")
            except (rosgraph.MasterError, OSError) as error:
                raise CheckError("cannot list the master's topics: {}".format(error)) from None
            return {name[:-len("/result")]: topic_type[:-len("ActionResult")] for name, topic_type in topics
                    if name.endswith("/result") and topic_type.endswith("ActionResult")}

        def match(spec, results):
            wanted = expected[spec.name]
            named_type = results.get(spec.name)
            if named_type is not None and named_type.split("/")[-1] == wanted:
                return named_type, None, []
            wrong_name = None
            if named_type is not None:
                wrong_name = "{} serves action type {}, not {}".format(spec.name, named_type, spec.type)
            candidates = [(name, topic_type) for name, topic_type in sorted(results.items())
                          if name not in expected and topic_type.split("/")[-1] == wanted]
            return None, wrong_name, candidates

        return self._discover("action", specs, by_type_grace_s, snapshot, match)

    # ---- the robot --------------------------------------------------------------------------------------------------

    def stop_robot(self):
        if self.robot:
            self._cmd_vel.publish(Twist())

    def prepare(self, still_timeout_s):
        """Open the check's interference window, zero /cmd_vel, reset the world through the ground-truth channel,
        and wait until the robot is at rest (CheckError if it is not)."""
        self._check_running()
        if not self.robot:
            return
        self._wait_commands_heard()
        self.timeline.lap("heard")
        self._window = self._truth.mark()
        self._watch.restart()
        self.stop_robot()
        reset_s = self._truth.request("reset_world")["t"]
        self.stop_robot()
        self.timeline.lap("reset")
        deadline = time.monotonic() + still_timeout_s
        while True:
            after = [sample for sample in self._truth.since(self._window).samples
                     if sample.t >= reset_s + RESET_MARGIN_S]
            tail = after[-STILL_SAMPLES:]
            if len(tail) == STILL_SAMPLES and all(is_still(sample) for sample in tail) \
                    and tail[-1].t >= reset_s + SENSORS_AFTER_RESET_S:
                self.timeline.lap("rest")
                return
            self._check_running()
            self._check_interference()
            if time.monotonic() > deadline:
                self._raise_if_interfered()
                if not after:
                    raise CheckError("no ground truth within {:.0f} s after the reset: is the simulator "
                                     "running?".format(still_timeout_s))
                latest = after[-1]
                raise CheckError("the robot did not come to rest within {:.0f} s after the reset (v={:.3f} m/s, "
                                 "w={:.3f} rad/s): is a node still driving it?".format(
                                     still_timeout_s, round(latest.v, 3) + 0.0, round(latest.w, 3) + 0.0))
            self._truth.wait(WAIT_SLICE_WALL_S)

    def _wait_commands_heard(self):
        """Wait (wall, at most COMMANDS_HEARD_WALL_S) until the simulator is connected to every node that publishes
        /cmd_vel on the master (lab_grader.checks.command_links). The simulator is asked at the XML-RPC URI its
        private channel gave; a publisher it is still not connected to by then, or a master or simulator that does
        not answer, is left to the check."""
        master = rosgraph.Master(rospy.get_name())
        simulator = xmlrpc.client.ServerProxy(self._truth.identity["uri"])
        deadline = time.monotonic() + COMMANDS_HEARD_WALL_S
        while True:
            try:
                publishers = dict(master.getSystemState()[0]).get(CMD_VEL_TOPIC, [])
                uris = {master.lookupNode(node) for node in publishers}
                bus_info = simulator.getBusInfo(rospy.get_name())[2]
            except (rosgraph.MasterError, OSError, xmlrpc.client.Error):
                return
            if not command_links.unheard(uris, bus_info, CMD_VEL_TOPIC) or time.monotonic() > deadline:
                return
            self._check_running()
            time.sleep(WAIT_SLICE_WALL_S)

    # ---- one graded call ------------------------------------------------------------------------------------------

    def observe(self, service: FoundService, request_fields, timeout_s, settle_s, measure_front=False):
        """Call `service.found` with `request_fields` and record what the robot does (motion.Observation)."""
        srv_class = service_class(service.expected_type)
        try:
            request = srv_class._request_class(**request_fields)
        except (AttributeError, TypeError) as error:
            raise CheckError("bad request for {}: {}".format(service.expected_type, error)) from None
        proxy = rospy.ServiceProxy(service.found, srv_class)
        origin, recording = (self._truth.latest, self._truth.mark()) if self.robot else (None, None)
        error = reply = replied_s = None
        front, front_measured = None, False
        sent_s = self.now()
        call = _Call(proxy, request, self.now)
        answered = self._wait_sim(sent_s + timeout_s, call.done.is_set)
        self.timeline.lap("reply")
        if not answered:
            error = "no reply within {:g} s of sim time".format(timeout_s)
        elif call.error is not None:
            error = call.error
        else:
            reply, replied_s = message_dict(call.reply), call.replied_s
            if self.robot:
                self._wait_sim(replied_s + settle_s)
                self.timeline.lap("tail")
            if measure_front:
                front, front_measured = self._truth.request("front_distance")["front_m"], True
                self.timeline.lap("front")
        samples, interfered = None, ()
        if self.robot:
            samples = ((origin,) if origin is not None else ()) + self._truth.since(recording).samples
            interfered = tuple(self._findings())
        return Observation(request=dict(request_fields), reply=reply, error=error, sent_s=sent_s,
                           replied_s=replied_s, samples=samples, front_distance_m=front,
                           front_measured=front_measured, server_error=answered and call.server_error,
                           interference=interfered)

    # ---- one graded goal --------------------------------------------------------------------------------------------

    def _action_client(self, action: FoundService):
        made = self._action_clients.get(action.found)
        if made is None:
            client = actionlib.SimpleActionClient(action.found, action_message_class(action.expected_type, "Action"))
            recorder = _FeedbackRecorder(action.found, action_message_class(action.expected_type, "ActionFeedback"),
                                         self.now)
            deadline = time.monotonic() + ACTION_CONNECT_WALL_S
            if not (client.wait_for_server(rospy.Duration(ACTION_CONNECT_WALL_S))
                    and _wait_wall(deadline, recorder.connected)):
                raise CheckError("the action client could not connect to {} within {:.0f} s".format(
                    action.found, ACTION_CONNECT_WALL_S))
            made = self._action_clients[action.found] = (client, recorder)
        return made

    def observe_action(self, action: FoundService, goal_fields, timeout_s, cancel_after_s=None, settle_s=0.0,
                       measure_front=False):
        """Send one goal with `goal_fields` to `action.found` and record how it went (an ActionObservation)."""
        client, recorder = self._action_client(action)
        self.timeline.lap("client")
        origin, recording = (self._truth.latest, self._truth.mark()) if self.robot else (None, None)

        def robot_record(ended_s):
            """The samples, front distance and interference of the goal (nothing without a robot)."""
            if not self.robot:
                return {}
            front = {}
            if ended_s is not None:
                self._wait_sim(ended_s + settle_s)
                self.timeline.lap("tail")
                if measure_front:
                    front = dict(front_distance_m=self._truth.request("front_distance")["front_m"],
                                 front_measured=True)
                    self.timeline.lap("front")
            samples = ((origin,) if origin is not None else ()) + self._truth.since(recording).samples
            return dict(front, samples=samples, interference=tuple(self._findings()))

        try:
            goal = action_message_class(action.expected_type, "Goal")(**goal_fields)
        except (AttributeError, TypeError) as error:
            raise CheckError("bad goal for {}: {}".format(action.expected_type, error)) from None
        ended = threading.Event()
        outcome = {}

        def on_done(state, result):
            outcome.update(state=state, result=None if result is None else message_dict(result), ended_s=self.now())
            ended.set()

        sent_s = self.now()
        client.send_goal(goal, done_cb=on_done)
        goal_id = client.gh.comm_state_machine.action_goal.goal_id.id

        def feedback():
            return tuple(recorder.of_goal(goal_id, sent_s))

        cancelled_s = None
        if cancel_after_s is not None and not self._wait_sim(sent_s + cancel_after_s, ended.is_set):
            cancelled_s = self.now()
            client.cancel_goal()
        ended_in_time = self._wait_sim(sent_s + timeout_s, ended.is_set)
        self.timeline.lap("result")
        if not ended_in_time:
            client.cancel_goal()
            return ActionObservation(dict(goal_fields), None, "", None, feedback(), sent_s, cancelled_s, None,
                                     error="no result within {:g} s".format(timeout_s), **robot_record(None))
        return ActionObservation(dict(goal_fields), STATE_NAMES.get(outcome["state"], str(outcome["state"])),
                                 client.get_goal_status_text() or "", outcome["result"], feedback(), sent_s,
                                 cancelled_s, outcome["ended_s"], **robot_record(outcome["ended_s"]))

    # ---- one run ----------------------------------------------------------------------------------------------------

    def observe_run(self, duration_s, start_s):
        """Tell the grader to start the run's node (create `ready_path`), then record the robot until `duration_s`
        of sim time after it first moved, or, if it never moves, until `start_s` of sim time and of wall time have
        both passed (a RunObservation). The wall-clock floor is for the node's start-up: Python and OpenCV imports
        take wall time, which a loaded machine stretches: at factor 2 and load 20, a sample line follower had not
        moved after 60 s of sim time, 30 wall seconds. The robot must have been prepared."""
        if not self.robot:
            raise CheckError("a run needs a robot: the suite has no world")
        origin, recording = self._truth.latest, self._truth.mark()
        started_s = self.now()
        if self.ready_path is not None:
            with open(self.ready_path, "w") as ready:
                ready.write("{:.3f}\n".format(started_s))
        first_motion = []

        def moved():
            latest = self._truth.latest
            if not first_motion and latest is not None and not is_still(latest):
                first_motion.append(latest.t)
            return bool(first_motion)

        def over():
            if not (self.ended_path and os.path.exists(self.ended_path)):
                return False
            latest = self._truth.latest
            if latest is None or not is_still(latest):
                rested_since[:] = []
                return False
            rested_since[:] = rested_since or [latest.t]
            return latest.t - rested_since[0] >= RESTED_AFTER_END_S

        rested_since = []
        has_moved = self._wait_sim(started_s + start_s, moved, at_least_wall_s=start_s)
        self.timeline.lap("first motion")
        if has_moved:
            self._wait_sim(first_motion[0] + duration_s, over)
            self.timeline.lap("recording")
        samples = ((origin,) if origin is not None else ()) + self._truth.since(recording).samples
        return RunObservation(started_s, samples, tuple(self._findings()))

    def inspect_images(self, named):
        """The images in the folder the result text `named` names, under the student's HOME (an ImageFolder)."""
        return image_folder.inspect(named, self.student_home)

    def shutdown(self):
        """Stop the robot, close the ground-truth channel and leave the graph (abandoned call threads die with the
        process)."""
        if not rospy.is_shutdown():
            self.stop_robot()
            rospy.signal_shutdown("checks done (pid {})".format(os.getpid()))
        if self.robot:
            self._truth.close()
