"""The grader's hands on the ROS graph during a check run: the only module of lab_grader.checks that imports rospy.

`GradingContext` is one rospy node (`/lab_grader_checks_<pid>...`, anonymous) in the graph of the simulator and
the student's nodes. It
- finds the services a suite expects the way a marker would (`find_services`): by the name the course asks for,
  if it has the expected md5sum; else any service on the master whose md5sum is the expected type's (a
  student's com2009_msgs/SetBool serves for tuos_msgs/SetBool). The md5sum and type come from the service's own
  TCPROS header (a probe, as `rosservice type` does), so a type the grader cannot import is still recognised;
- prepares the robot before each check (`prepare`): zero /cmd_vel (tb3_sim holds the last command),
  /gazebo/reset_world, then waits until /odom reports the robot at rest (STILL_SAMPLES consecutive still samples
  stamped RESET_MARGIN_S or more after the reset returned, within `still_timeout_s` wall seconds);
- makes one graded call (`observe`): records ground-truth /odom (tb3_sim's has no noise) from before the call,
  calls the service on a daemon thread, waits for the reply for at most `timeout_s` seconds of SIM time (rospy
  time under /use_sim_time, so the verdict does not depend on the simulator's real-time factor), keeps recording
  for `settle_s` of sim time after the reply, and, if asked, reads the front LiDAR distance from the first /scan
  stamped after that. A call with no reply in time is abandoned on its thread (a hung student callback cannot be
  interrupted from the client side; the daemon thread dies with the runner), and the observation says
  "no reply within N s of sim time".

- finds the actionlib servers a suite expects (`find_actions`): by the course's namespace when its
  <ns>/result topic carries the expected <Name>ActionResult type, else any namespace whose result topic has a type
  of the same name in another package (com2009_msgs/counterActionResult for beginner_tutorials/counter). The
  master knows topic types by name only, so the name is what is compared; the client's md5sum check on
  connecting rejects a look-alike of another layout;
- sends one graded goal (`observe_action`): records every feedback message, cancels the goal `cancel_after_s`
  after sending it if asked, and waits at most `timeout_s` for it to end, all in ROS time.

A suite without a world has no robot (`robot=False`): no /odom, /scan or /cmd_vel, nothing to reset, ROS time is
wall time, and observations carry no samples.

Sim-time waits are guarded in wall time: if the simulated clock does not advance for CLOCK_STALL_WALL_S wall
seconds (the simulator died or is paused), the wait ends with a CheckError instead of hanging the runner.
Topics and services are tb3_sim's single robot in the root namespace: /odom, /scan, /cmd_vel, /gazebo/reset_world.
"""
import math
import os
import re
import threading
import time
from typing import Dict, Sequence

import actionlib
import genpy
import rosgraph
import roslib.message
import rospy
import rosservice
from actionlib_msgs.msg import GoalStatus
from geometry_msgs.msg import Twist
from nav_msgs.msg import Odometry
from sensor_msgs.msg import LaserScan
from std_srvs.srv import Empty

from lab_grader.checks.action_checks import ActionObservation
from lab_grader.checks.motion import Observation, Sample, front_distance, is_still
from lab_grader.checks.verdicts import CheckError, FoundService, Interrupted
from lab_grader.suite_file import GOAL_STATES

NODE_NAME = "lab_grader_checks"
ODOM_TOPIC = "/odom"
SCAN_TOPIC = "/scan"
CMD_VEL_TOPIC = "/cmd_vel"
RESET_SERVICE = "/gazebo/reset_world"
FIRST_CLOCK_WALL_S = 30.0      # wait this long for the first /clock (and /odom) before giving up
CLOCK_STALL_WALL_S = 10.0      # sim time frozen this long during a sim-time wait: the simulator is gone
RESET_TIMEOUT_WALL_S = 10.0    # /gazebo/reset_world must be available (and answer) within this
CMD_VEL_CONNECT_WALL_S = 5.0   # wait this long for the simulator to connect to our /cmd_vel publisher
STILL_SAMPLES = 3              # consecutive still /odom samples (0.1 s at 30 Hz) after a reset = at rest
RESET_MARGIN_S = 0.1           # only /odom stamped this much sim time after the reset returned counts as "after":
                               # our /clock may lag the simulator's, and a pre-reset sample must never be the origin
FRONT_SCAN_WAIT_SIM_S = 2.0    # a fresh /scan (5 Hz) must come within this much sim time
ACTION_CONNECT_WALL_S = 5.0    # an action client must connect to the server's topics within this
SERVER_ERROR_TEXT = "responded with an error"   # rospy's words for a server's error answer (its callback raised)
SERVER_ERROR_BYTES = re.compile(r"(responded with an error: )b(['\"])(.*)\2$", re.DOTALL)
POLL_WALL_S = 0.2              # service discovery polls the master this often
STATE_NAMES = {getattr(GoalStatus, name): name for name in GOAL_STATES}   # 3 -> "SUCCEEDED"
WAIT_SLICE_WALL_S = 0.01
ODOM_QUEUE = 100               # no /odom sample is dropped while the runner is busy (30 Hz x the real-time factor)


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


def service_class(type_name):
    """The Python class of service type `type_name` (CheckError when it cannot be imported)."""
    return _load_class(roslib.message.get_service_class, type_name, "service", type_name)


def _yaw(orientation):
    q = orientation
    return math.atan2(2.0 * (q.w * q.z + q.x * q.y), 1.0 - 2.0 * (q.y * q.y + q.z * q.z))


class _Call:
    """One service call on a daemon thread; `done` is set when it returned or raised."""

    def __init__(self, proxy, request):
        self.reply = None
        self.error = None
        self.server_error = False
        self.replied_s = None
        self.done = threading.Event()
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
            self.replied_s = rospy.get_rostime().to_sec()
            self.done.set()


class GradingContext:
    """See the module docstring. Create it once per run (it calls rospy.init_node)."""

    def __init__(self, robot=True):
        rospy.init_node(NODE_NAME, anonymous=True)
        self.robot = robot
        self._changed = threading.Condition()
        self._recording = None            # a list while observe() records, else None
        self._latest = None               # the latest Sample
        self._rest_from_s = math.inf      # prepare(): count still samples stamped from this sim time on ...
        self._rest_count = 0              # ... consecutive ones, up to the latest
        self._scan = None                 # the latest LaserScan
        self._action_clients = {}         # action name -> SimpleActionClient, made once
        self._sim_seen = (None, time.monotonic())   # (last sim time seen, wall time it changed)
        if not robot:
            return
        self._cmd_vel = rospy.Publisher(CMD_VEL_TOPIC, Twist, queue_size=1)
        self._reset = rospy.ServiceProxy(RESET_SERVICE, Empty)
        rospy.Subscriber(ODOM_TOPIC, Odometry, self._on_odom, queue_size=ODOM_QUEUE)
        rospy.Subscriber(SCAN_TOPIC, LaserScan, self._on_scan, queue_size=1)

    # ---- subscriptions ------------------------------------------------------------------------------------------

    def _on_odom(self, msg):
        pose, twist = msg.pose.pose, msg.twist.twist
        sample = Sample(msg.header.stamp.to_sec(), pose.position.x, pose.position.y, _yaw(pose.orientation),
                        twist.linear.x, twist.angular.z)
        with self._changed:
            self._latest = sample
            if sample.t >= self._rest_from_s:
                self._rest_count = self._rest_count + 1 if is_still(sample) else 0
            if self._recording is not None:
                self._recording.append(sample)
            self._changed.notify_all()

    def _on_scan(self, msg):
        with self._changed:
            self._scan = msg
            self._changed.notify_all()

    # ---- time -----------------------------------------------------------------------------------------------------

    def now(self):
        """rospy time in seconds: sim time under /use_sim_time."""
        return rospy.get_rostime().to_sec()

    def _check_running(self):
        if rospy.is_shutdown():
            raise Interrupted("the runner was interrupted (rospy shut down)")

    def _check_clock(self):
        """CheckError when the sim clock has not advanced for CLOCK_STALL_WALL_S wall seconds."""
        now, wall = self.now(), time.monotonic()
        seen, since = self._sim_seen
        if now != seen:
            self._sim_seen = (now, wall)
        elif wall - since > CLOCK_STALL_WALL_S:
            raise CheckError("simulated time stopped at {:.2f} s for {:.0f} s of wall time: is the simulator "
                             "running?".format(now, CLOCK_STALL_WALL_S))

    def _wait_sim(self, until_s, done=lambda: False):
        """Wait until `done()` (True) or sim time `until_s` (False), watching for a stalled clock and shutdown."""
        self._sim_seen = (None, time.monotonic())
        while True:
            if done():
                return True
            if self.now() >= until_s:
                return False
            self._check_running()
            self._check_clock()
            with self._changed:
                self._changed.wait(WAIT_SLICE_WALL_S)

    def wait_until_ready(self):
        """Wait (wall, FIRST_CLOCK_WALL_S) for the first /clock and /odom and for tb3_sim to subscribe /cmd_vel."""
        if not self.robot:
            return
        deadline = time.monotonic() + FIRST_CLOCK_WALL_S
        while rospy.get_rostime().is_zero() or self._latest is None:
            self._check_running()
            if time.monotonic() > deadline:
                missing = "/clock" if rospy.get_rostime().is_zero() else ODOM_TOPIC
                raise CheckError("no {} after {:.0f} s: is tb3_sim running on {}?".format(
                    missing, FIRST_CLOCK_WALL_S, rosgraph.get_master_uri()))
            time.sleep(WAIT_SLICE_WALL_S)
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
        the module docstring. Returns {spec.name: FoundService}, `found` being the action namespace."""
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
        """Zero /cmd_vel, reset the world, and wait until the robot is at rest (CheckError if it is not)."""
        self._check_running()
        if not self.robot:
            return
        self.stop_robot()
        try:
            self._reset.wait_for_service(RESET_TIMEOUT_WALL_S)
            self._reset()
        except (rospy.ROSException, rospy.ServiceException) as error:
            raise CheckError("{} failed: {}".format(RESET_SERVICE, error)) from None
        self.stop_robot()
        deadline = time.monotonic() + still_timeout_s
        with self._changed:
            self._rest_from_s, self._rest_count = self.now() + RESET_MARGIN_S, 0
            while self._rest_count < STILL_SAMPLES:
                self._check_running()
                if time.monotonic() > deadline:
                    latest = self._latest
                    if latest is None or latest.t < self._rest_from_s:
                        raise CheckError("no {} within {:.0f} s after {}: is the simulator running?".format(
                            ODOM_TOPIC, still_timeout_s, RESET_SERVICE))
                    raise CheckError("the robot did not come to rest within {:.0f} s after {} (v={:.3f} m/s, "
                                     "w={:.3f} rad/s): is a node still driving it?".format(
                                         still_timeout_s, RESET_SERVICE, round(latest.v, 3) + 0.0,
                                         round(latest.w, 3) + 0.0))
                self._changed.wait(WAIT_SLICE_WALL_S)

    def _front_distance_after(self, after_s):
        """The front LiDAR distance from the first /scan stamped at or after sim time `after_s`."""
        def fresh():
            return self._scan is not None and self._scan.header.stamp.to_sec() >= after_s
        if not self._wait_sim(self.now() + FRONT_SCAN_WAIT_SIM_S, fresh):
            raise CheckError("no {} within {:.0f} s of sim time".format(SCAN_TOPIC, FRONT_SCAN_WAIT_SIM_S))
        scan = self._scan
        return front_distance(scan.ranges, scan.angle_min, scan.angle_increment, scan.range_min)

    # ---- one graded call ------------------------------------------------------------------------------------------

    def observe(self, service: FoundService, request_fields, timeout_s, settle_s, measure_front=False):
        """Call `service.found` with `request_fields` and record what the robot does (motion.Observation)."""
        srv_class = service_class(service.expected_type)
        try:
            request = srv_class._request_class(**request_fields)
        except (AttributeError, TypeError) as error:
            raise CheckError("bad request for {}: {}".format(service.expected_type, error)) from None
        proxy = rospy.ServiceProxy(service.found, srv_class)
        with self._changed:
            self._recording = [self._latest] if self._latest is not None else []
        error = reply = replied_s = None
        front, front_measured = None, False
        try:
            sent_s = self.now()
            call = _Call(proxy, request)
            answered = self._wait_sim(sent_s + timeout_s, call.done.is_set)
            if not answered:
                error = "no reply within {:g} s of sim time".format(timeout_s)
            elif call.error is not None:
                error = call.error
            else:
                reply, replied_s = message_dict(call.reply), call.replied_s
                if self.robot:
                    self._wait_sim(replied_s + settle_s)
                if measure_front:
                    front, front_measured = self._front_distance_after(self.now()), True
        finally:
            with self._changed:
                samples, self._recording = tuple(self._recording), None
        return Observation(request=dict(request_fields), reply=reply, error=error, sent_s=sent_s,
                           replied_s=replied_s, samples=samples if self.robot else None, front_distance_m=front,
                           front_measured=front_measured, server_error=answered and call.server_error)

    # ---- one graded goal --------------------------------------------------------------------------------------------

    def _action_client(self, action: FoundService):
        client = self._action_clients.get(action.found)
        if client is None:
            client = actionlib.SimpleActionClient(action.found, action_message_class(action.expected_type, "Action"))
            if not client.wait_for_server(rospy.Duration(ACTION_CONNECT_WALL_S)):
                raise CheckError("the action client could not connect to {} within {:.0f} s".format(
                    action.found, ACTION_CONNECT_WALL_S))
            self._action_clients[action.found] = client
        return client

    def observe_action(self, action: FoundService, goal_fields, timeout_s, cancel_after_s=None):
        """Send one goal with `goal_fields` to `action.found` and record how it went (an ActionObservation)."""
        client = self._action_client(action)
        try:
            goal = action_message_class(action.expected_type, "Goal")(**goal_fields)
        except (AttributeError, TypeError) as error:
            raise CheckError("bad goal for {}: {}".format(action.expected_type, error)) from None
        feedback, ended = [], threading.Event()
        outcome = {}

        def on_feedback(message):
            feedback.append((self.now() - sent_s, message_dict(message)))

        def on_done(state, result):
            outcome.update(state=state, result=None if result is None else message_dict(result), ended_s=self.now())
            ended.set()

        sent_s = self.now()
        client.send_goal(goal, done_cb=on_done, feedback_cb=on_feedback)
        cancelled_s = None
        if cancel_after_s is not None and not self._wait_sim(sent_s + cancel_after_s, ended.is_set):
            cancelled_s = self.now()
            client.cancel_goal()
        if not self._wait_sim(sent_s + timeout_s, ended.is_set):
            client.cancel_goal()
            return ActionObservation(dict(goal_fields), None, "", None, tuple(feedback), sent_s, cancelled_s, None,
                                     error="no result within {:g} s".format(timeout_s))
        return ActionObservation(dict(goal_fields), STATE_NAMES.get(outcome["state"], str(outcome["state"])),
                                 client.get_goal_status_text() or "", outcome["result"], tuple(feedback), sent_s,
                                 cancelled_s, outcome["ended_s"])

    def shutdown(self):
        """Stop the robot and leave the graph (abandoned call threads die with the process)."""
        if not rospy.is_shutdown():
            self.stop_robot()
            rospy.signal_shutdown("checks done (pid {})".format(os.getpid()))
