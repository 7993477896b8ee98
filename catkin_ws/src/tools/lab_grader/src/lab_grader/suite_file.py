"""A grading suite as data: load and validate a suite YAML file (suites/<name>.yaml) into typed objects.

Plain Python (PyYAML, and rospkg to find the package's suites/ folder). `load_suite("week4")` loads this package's
suites/week4.yaml, `load_suite("path/to/file.yaml")` any file. Every unknown key and every bad value is a
`SuiteError` naming the file and the key path (`week4.yaml: checks[2].expect.motion.forward_m.min: expected a
finite number, got 'abc'`), so a typo in a suite fails loudly instead of silently grading with a default.

The format (suites/week4.yaml is the worked example, with a comment on every key):

    suite: week4                      # the suite's name (letters, digits, _ and -), written into the results
    title: Week 4 - ROS Services      # optional, free text
    world: approach_arena             # optional: the tb3_sim world the orchestrator starts (roslaunch tb3_sim
                                      #   tb3_sim.launch world:=approach_arena); without it only a master runs, and
                                      #   checks may not expect motion or a LiDAR distance
    simulator_args: {camera_width: 640}   # optional: more tb3_sim.launch args (name: value), with a world only
    real_time_factor: 1.0             # optional (1.0): the simulator speed the orchestrator grades at
    settle_s: 1.0                     # optional (1.0): sim s recorded after each reply; "left still" is judged then
    timeout_s: 30                     # optional (30): default reply timeout of a check, sim s
    still_timeout_s: 10               # optional (10): wall s to wait for the robot to rest before a check
    by_type_grace_s: 3                # optional (3): wall s to keep waiting for the course's name once only a
                                      #   service of the right type (another name) is on the master
    services:                         # what the course asks the student to serve
      - name: /move_service           # the name the course asks for (absolute)
        type: tuos_msgs/SetBool       # its type; another type with the same md5sum is accepted by type
        node: move_server.py          # the file the course has the student write and start (rosrun <package>
                                      #   move_server.py); the services and actions of one file make one
                                      #   exercise, whose node the grader runs alone during its checks
        wait_s: 30                    # optional (30): wall s to wait for it to appear on the master
    actions:                          # optional: actionlib servers the course asks for
      - name: /my_action_server       # the action namespace the course asks for (absolute)
        type: beginner_tutorials/counter  # the action type; another package's <Name>Action (the same name) is
        node: counter_server.py       #   accepted by type
        wait_s: 30
    checks:
      - id: move_true                 # unique; lower case, digits and _
        title: ...                    # one line for the report: what is asked and the tolerance allowed
        kind: required                # optional (required): what the course page asks; `advice`: robustness
                                      #   beyond the page, reported but worth 0 points unless given a weight
        weight: 16                    # points (>= 0) a pass is worth; required for a required check, 0 by
                                      #   default for advice
        service: /move_service        # one of services[].name (or `action:`, see below)
        request: {request_signal: true}   # request fields (bool, int, float incl. .nan, str)
        timeout_s: 15                 # optional (suite's timeout_s): sim s to wait for the reply
        expect:                       # optional: nothing = any reply passes
          reply: {response_signal: true}          # reply fields that must be equal
          reply_matches: {response_message: "(?i)stop"}   # reply fields that must match a regex (re.search)
          refused: true               # the call must fail (the server raised) instead of replying
          motion:                     # see lab_grader.checks.motion for the quantities
            forward_m: {value: 0.5, tolerance: 0.1}   # a range: {value, tolerance} or {min} / {max} / {min, max}
            lateral_max_m: 0.05       # |lateral_m| <= this
            turn_deg: {min: 5}        # signed heading change range (CCW positive)
            turn_max_deg: 5           # |turn_deg| <= this
            duration_s: {value: 5, tolerance: 0.5}    # motion start to stop, sim s
            excursion_max_m: 0.01     # never farther than this from the start ("no motion")
            mean_speed_mps: {value: 0.1, tolerance: 0.02}  # forward_m / duration_s: the speed it drove at
            still_at_end: true        # |v| < 0.01 m/s and |w| < 0.01 rad/s settle_s after the reply
          front_distance_m: {value: 0.4, tolerance: 0.05}  # closest LiDAR return within +-20 deg, once still
      - id: count_three               # an action check: send a goal, maybe cancel it, judge how it ended
        title: ...
        weight: 30
        action: /my_action_server     # one of actions[].name
        goal: {num_counts: 3}         # goal fields
        cancel_after_s: 2.5           # optional: cancel the goal this long (s) after sending it
        timeout_s: 10                 # optional (suite's timeout_s): s to wait for the goal to end
        expect:
          state: SUCCEEDED            # the terminal state, or a list of accepted ones (actionlib GoalStatus names)
          result: {result_message: "Counting complete!"}     # result fields that must be equal
          result_matches: {result_message: "(?i)complete"}   # result fields that must match a regex
          feedback: {counts_elapsed: [0, 1, 2]}  # every feedback message's field value, in order
          duration_s: {value: 3, tolerance: 0.5}   # goal sent to goal ended, s
          cancel_to_end_s: {max: 1.5}  # cancel sent to goal ended, s
          result_ranges: {total_distance_travelled: {min: 0.5}}   # numeric result fields within a range
          feedback_count: {min: 4}     # how many feedback messages the goal sent
          feedback_rising: [current_distance_travelled]   # fields that never decrease from one feedback to the next
          motion: {turn_deg: {value: 90, tolerance: 5}}   # with a world: as a service check's, from the goal sent
                                       #   to settle_s after it ended (the robot is reset and still before)
          front_distance_m: {value: 0.4, tolerance: 0.05}  # with a world: as a service check's, once still
          images: {path_field: image_path, count: 4}   # the result field naming a folder ("~/..." = the student's
                                       #   HOME) that must hold `count` image files, every one decodable

A node that serves nothing but drives the robot (Part 6's colour search and line follower) is a `run`: the grader
resets the robot, starts the student's node alone and records the robot's true motion until `duration_s` of sim
time after it first moved (its start-up, however slow the machine, is not counted); every check of that run is
judged on the one recording (lab_grader.checks.run_checks documents the quantities):

    runs:
      - node: colour_search.py        # the course's file name (rosrun <package> colour_search.py)
        duration_s: 75                # sim s recorded from the robot's first motion on
        start_s: 60                   # optional (60): s from the reset for the robot's first motion, in sim time
                                      #   and at least as many wall s for the node's start-up (else the recording
                                      #   ends there: a node that never moves the robot)
      - node: line_follower.py
        duration_s: 45
        world: tuos_simulations/worlds/line_following.yaml   # optional (the suite's world, which a suite with runs
                                      #   must have): this run's world, a tb3_sim world name or <package>/<path of
                                      #   a world file in it>; the grader starts a simulator of its own for it
        simulator_args: {x_pos: 2.4, y_pos: -2.5, yaw: 3.14}   # optional (the suite's): this run's tb3_sim args
    checks:
      - id: faces_blue
        title: ...
        weight: 40
        run: colour_search.py         # one of runs[].node
        expect:                       # one or more of the kinds in RUN_EXPECT_PARSERS
          stops_facing:               # it stops (still >= still_s after it first moved) facing each of `faces`
            faces: [blue]
            landmarks: {blue: [0.6, -0.6], red: [0.6, 0.6]}   # named points (x, y in m) it may face
            tolerance_deg: 10         # |bearing from the true heading to the point|
            still_s: 1.0
      - id: follows_the_line
        title: ...
        weight: 30
        run: line_follower.py
        expect:
          line:                       # a line on the floor: a chain of cubic Beziers (start, then 3 points each)
            points: [[2.38, -2.5], ...]
            progress_m: {min: 4}      # arc length reached before it first left the line (> leave_m from it)
            leave_m: 0.15
            mean_distance_m: {max: 0.05}   # the true position's distance to the line, over the samples after it
            max_distance_m: {max: 0.15}    #   first moved
"""
import math
import re
from pathlib import Path
from typing import Any, Dict, List, NamedTuple, Optional, Tuple

import rospkg
import yaml

from lab_grader.errors import GraderError

PACKAGE = "lab_grader"
SUITE_SUFFIX = ".yaml"
DEFAULT_REAL_TIME_FACTOR = 1.0
DEFAULT_SETTLE_S = 1.0
DEFAULT_TIMEOUT_S = 30.0
DEFAULT_STILL_TIMEOUT_S = 10.0
DEFAULT_BY_TYPE_GRACE_S = 3.0
DEFAULT_WAIT_S = 30.0
DEFAULT_START_S = 60.0
SUITE_NAME = re.compile(r"^[A-Za-z0-9_-]+$")
CHECK_ID = re.compile(r"^[a-z][a-z0-9_]*$")
FIELD_NAME = re.compile(r"^[A-Za-z_][A-Za-z0-9_]*$")
SERVICE_NAME = re.compile(r"^(/[A-Za-z][A-Za-z0-9_]*)+$")
FILE_NAME = re.compile(r"^[A-Za-z0-9_.+-]+$")
TYPE_NAME = re.compile(r"^[A-Za-z][A-Za-z0-9_]*/[A-Za-z][A-Za-z0-9_]*$")
SUITE_KEYS = ("suite", "title", "world", "simulator_args", "real_time_factor", "settle_s", "timeout_s",
              "still_timeout_s", "by_type_grace_s", "services", "actions", "runs", "checks")
RUN_KEYS = ("node", "duration_s", "start_s", "world", "simulator_args")
RUN_CHECK_KEYS = ("id", "title", "kind", "weight", "run", "expect")
STOPS_FACING_KEYS = ("faces", "landmarks", "tolerance_deg", "still_s")
LINE_KEYS = ("points", "progress_m", "leave_m", "mean_distance_m", "max_distance_m")
SERVICE_KEYS = ("name", "type", "node", "wait_s")
SERVICE_CHECK_KEYS = ("id", "title", "kind", "weight", "service", "request", "timeout_s", "expect")
ACTION_CHECK_KEYS = ("id", "title", "kind", "weight", "action", "goal", "cancel_after_s", "timeout_s", "expect")
REQUIRED = "required"
ADVICE = "advice"
CHECK_KINDS = (REQUIRED, ADVICE)
EXPECT_KEYS = ("reply", "reply_matches", "refused", "motion", "front_distance_m")
ACTION_EXPECT_KEYS = ("state", "result", "result_matches", "feedback", "duration_s", "cancel_to_end_s",
                      "result_ranges", "feedback_count", "feedback_rising", "motion", "front_distance_m", "images")
IMAGES_KEYS = ("path_field", "count")
ROBOT_EXPECT_KEYS = ("motion", "front_distance_m")
GOAL_STATES = ("PENDING", "ACTIVE", "PREEMPTED", "SUCCEEDED", "ABORTED", "REJECTED", "PREEMPTING", "RECALLING",
               "RECALLED", "LOST")
RANGE_KEYS = ("min", "max", "value", "tolerance")


class SuiteError(GraderError):
    """A suite file that cannot be used; the message names the file and the key."""


class Range(NamedTuple):
    """A closed interval; either end may be open (None)."""

    min: Optional[float]
    max: Optional[float]

    def contains(self, value):
        return (value is not None and math.isfinite(value) and (self.min is None or value >= self.min)
                and (self.max is None or value <= self.max))

    def describe(self, unit=""):
        """'0.40..0.60 m', 'at least 5 deg', 'at most 0.05 m'."""
        suffix = " " + unit if unit else ""
        if self.min is not None and self.max is not None:
            return "{:g}..{:g}{}".format(self.min, self.max, suffix)
        if self.min is not None:
            return "at least {:g}{}".format(self.min, suffix)
        return "at most {:g}{}".format(self.max, suffix)


class MotionExpectation(NamedTuple):
    forward_m: Optional[Range] = None
    lateral_max_m: Optional[float] = None
    turn_deg: Optional[Range] = None
    turn_max_deg: Optional[float] = None
    duration_s: Optional[Range] = None
    excursion_max_m: Optional[float] = None
    still_at_end: Optional[bool] = None
    mean_speed_mps: Optional[Range] = None


class Expectation(NamedTuple):
    reply: Dict[str, Any]
    reply_matches: Dict[str, "re.Pattern"]
    motion: Optional[MotionExpectation]
    front_distance_m: Optional[Range]
    refused: bool = False


class ImagesExpectation(NamedTuple):
    """The result field that names the folder of saved images, and how many it must hold."""

    path_field: str
    count: int


class ActionExpectation(NamedTuple):
    states: Tuple[str, ...]                 # accepted terminal states; empty = any
    result: Dict[str, Any]
    result_matches: Dict[str, "re.Pattern"]
    feedback: Dict[str, Tuple[Any, ...]]    # field -> its values over the feedback messages, in order
    duration_s: Optional[Range]
    cancel_to_end_s: Optional[Range]
    result_ranges: Dict[str, Range]         # numeric result field -> its range
    feedback_count: Optional[Range]
    feedback_rising: Tuple[str, ...]        # feedback fields that must never decrease
    motion: Optional[MotionExpectation]
    front_distance_m: Optional[Range]
    images: Optional[ImagesExpectation] = None


class StopsFacing(NamedTuple):
    """Stops facing each of `faces` (names of `landmarks`, points x, y in m) within `tolerance_deg`; a stop is
    `still_s` sim s or more of rest after the robot first moved."""

    faces: Tuple[str, ...]
    landmarks: Dict[str, Tuple[float, float]]
    tolerance_deg: float
    still_s: float


class LineExpectation(NamedTuple):
    """A line on the floor (cubic Beziers: the start point, then control 1, control 2, end for each) and what the
    robot's true path must do along it."""

    points: Tuple[Tuple[float, float], ...]
    leave_m: float
    progress_m: Optional[Range] = None
    mean_distance_m: Optional[Range] = None
    max_distance_m: Optional[Range] = None


class RunExpectation(NamedTuple):
    stops_facing: Optional[StopsFacing] = None
    line: Optional[LineExpectation] = None


class RunSpec(NamedTuple):
    """A node the course has the student write and run that serves nothing: graded by what the robot does in
    `duration_s` sim s from its first motion (which must come within `start_s` sim s of the reset), in `world` with
    `simulator_args` (None: the suite's)."""

    node: str
    duration_s: float
    world: Optional[str] = None
    simulator_args: Optional[Tuple[Tuple[str, Any], ...]] = None
    start_s: float = DEFAULT_START_S


class ServiceSpec(NamedTuple):
    """A service (or action) the course asks for: its name, type, the course's file that serves it, and how long
    (wall s) to wait for it on the master."""

    name: str
    type: str
    wait_s: float
    node: str


class Exercise(NamedTuple):
    """The services and actions one course file serves (suite order), and the ids of the checks that call them."""

    node: str
    services: Tuple[ServiceSpec, ...]
    actions: Tuple[ServiceSpec, ...]
    check_ids: Tuple[str, ...]
    run: Optional[RunSpec] = None       # a run (the node serves nothing): its recording's length and world


class CheckSpec(NamedTuple):
    """A service check (`service`, `request`, an Expectation), an action check (`action`, `goal`,
    `cancel_after_s`, an ActionExpectation) or a run check (`run`, a RunExpectation): the other kinds' fields are
    None."""

    id: str
    title: str
    weight: float
    service: Optional[str]
    request: Optional[Dict[str, Any]]
    timeout_s: float
    expect: Any
    action: Optional[str] = None
    goal: Optional[Dict[str, Any]] = None
    cancel_after_s: Optional[float] = None
    kind: str = REQUIRED
    run: Optional[str] = None


class Suite(NamedTuple):
    name: str
    title: str
    path: Path
    world: Optional[str]
    real_time_factor: float
    settle_s: float
    still_timeout_s: float
    by_type_grace_s: float
    services: Tuple[ServiceSpec, ...]
    checks: Tuple[CheckSpec, ...]
    actions: Tuple[ServiceSpec, ...] = ()
    simulator_args: Tuple[Tuple[str, Any], ...] = ()   # (tb3_sim.launch arg, value), in the file's order
    runs: Tuple[RunSpec, ...] = ()

    def launch_args(self, exercise=None):
        """The simulator's roslaunch args beyond world and gui (["camera_width:=640", ...]): the suite's, or those
        of `exercise`'s run when it has its own."""
        run = exercise.run if exercise is not None else None
        args = run.simulator_args if run is not None and run.simulator_args is not None else self.simulator_args
        return ["{}:={}".format(name, value) for name, value in args]

    def world_of(self, exercise=None):
        """The world `exercise` is graded in: its run's own, else the suite's."""
        run = exercise.run if exercise is not None else None
        return run.world if run is not None and run.world is not None else self.world

    @property
    def nodes(self):
        """The course's file names, each once, in the order the suite lists their services, actions and runs."""
        return tuple(dict.fromkeys(spec.node for spec in self.services + self.actions + self.runs))

    def exercises(self) -> Tuple[Exercise, ...]:
        """One Exercise per course file, in the suite's order."""
        return tuple(Exercise(node, tuple(spec for spec in self.services if spec.node == node),
                              tuple(spec for spec in self.actions if spec.node == node),
                              tuple(check.id for check in self.checks
                                    if check.run == node
                                    or any(spec.node == node and spec.name in (check.service, check.action)
                                           for spec in self.services + self.actions)),
                              next((run for run in self.runs if run.node == node), None))
                     for node in self.nodes)

    @property
    def max_score(self):
        """The sum of the checks' weights (an int when they are whole numbers)."""
        total = sum(check.weight for check in self.checks)
        return int(total) if float(total).is_integer() else total

    def service(self, name):
        return next(service for service in self.services if service.name == name)


class _Mapping:
    """A YAML mapping being read, with its key path for error messages. Keys outside `allowed` are rejected at
    once, before any value is read, so a misspelt key is reported as such rather than as a missing one."""

    def __init__(self, file_label, path, data, allowed):
        self.file_label = file_label
        self.path = path
        if not isinstance(data, dict):
            self.fail(path, "expected a mapping, got {}".format(_show(data)))
        for key in data:
            if not isinstance(key, str):
                self.fail(path, "keys must be strings, got {}".format(_show(key)))
        unknown = sorted(set(data) - set(allowed))
        if unknown:
            self.fail(self.where(unknown[0]), "unknown key (allowed: {})".format(", ".join(sorted(allowed))))
        self.data = data

    def where(self, key):
        return "{}.{}".format(self.path, key) if self.path else key

    def fail(self, where, problem):
        raise SuiteError("{}: {}: {}".format(self.file_label, where or "(top level)", problem))

    def get(self, key, convert, default=None, required=False):
        """`convert(value, where)` of `key`, `default` when absent (SuiteError if `required`)."""
        if key not in self.data:
            if required:
                self.fail(self.where(key), "missing (required)")
            return default
        return convert(self.data[key], self.where(key))


def _show(value):
    text = repr(value)
    return text if len(text) <= 60 else text[:57] + "..."


class _Converters:
    """Value checks bound to one file, each `(value, where) -> typed value` or SuiteError naming `where`."""

    def __init__(self, file_label):
        self.file_label = file_label

    def fail(self, where, problem):
        raise SuiteError("{}: {}: {}".format(self.file_label, where, problem))

    def number(self, value, where, minimum=None, positive=False):
        if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value):
            self.fail(where, "expected a finite number, got {}".format(_show(value)))
        if positive and value <= 0:
            self.fail(where, "must be > 0, got {}".format(_show(value)))
        if minimum is not None and value < minimum:
            self.fail(where, "must be >= {}, got {}".format(minimum, _show(value)))
        return float(value) if isinstance(value, float) else value

    def positive(self, value, where):
        return float(self.number(value, where, positive=True))

    def non_negative(self, value, where):
        return self.number(value, where, minimum=0)

    def text(self, value, where, pattern=None, what=None):
        if not isinstance(value, str) or not value.strip():
            self.fail(where, "expected a non-empty string, got {}".format(_show(value)))
        if pattern is not None and not pattern.match(value):
            self.fail(where, "{} is not {}".format(_show(value), what))
        return value

    def choice(self, value, where, choices):
        if value not in choices:
            self.fail(where, "expected one of {}, got {}".format(", ".join(choices), _show(value)))
        return value

    def boolean(self, value, where):
        if not isinstance(value, bool):
            self.fail(where, "expected true or false, got {}".format(_show(value)))
        return value

    def scalar(self, value, where):
        if not isinstance(value, (bool, int, float, str)):
            self.fail(where, "expected a bool, number or string, got {}".format(_show(value)))
        return value

    def regex(self, value, where):
        self.text(value, where)
        try:
            return re.compile(value)
        except re.error as error:
            self.fail(where, "not a valid regular expression ({})".format(error))

    def fields(self, value, where, convert):
        """A mapping of request/reply field names to values."""
        if not isinstance(value, dict):
            self.fail(where, "expected a mapping of field names, got {}".format(_show(value)))
        result = {}
        for key, item in value.items():
            if not isinstance(key, str) or not FIELD_NAME.match(key):
                self.fail(where, "{} is not a field name".format(_show(key)))
            result[key] = convert(item, "{}.{}".format(where, key))
        return result

    def range(self, value, where):
        mapping = _Mapping(self.file_label, where, value, RANGE_KEYS)
        low = mapping.get("min", self.number)
        high = mapping.get("max", self.number)
        centre = mapping.get("value", self.number)
        tolerance = mapping.get("tolerance", self.non_negative)
        if centre is not None or tolerance is not None:
            if centre is None or tolerance is None or low is not None or high is not None:
                self.fail(where, "give either value and tolerance, or min and/or max")
            return Range(float(centre - tolerance), float(centre + tolerance))
        if low is None and high is None:
            self.fail(where, "give either value and tolerance, or min and/or max")
        if low is not None and high is not None and low > high:
            self.fail(where, "min {} is greater than max {}".format(low, high))
        return Range(None if low is None else float(low), None if high is None else float(high))


def default_suites_dir() -> Path:
    """This package's suites/ folder: rospack's lab_grader, else the one next to this source tree."""
    try:
        return Path(rospkg.RosPack().get_path(PACKAGE)) / "suites"
    except rospkg.ResourceNotFound:
        return Path(__file__).resolve().parents[2] / "suites"


def load_suite(name_or_path, suites_dir=None) -> Suite:
    """Read and validate a suite: a name (`week4`: <suites_dir>/week4.yaml, by default this package's suites/) or
    a file path. SuiteError naming the file and key on any problem."""
    path = resolve_suite(name_or_path, default_suites_dir() if suites_dir is None else suites_dir)
    label = path.name
    try:
        data = yaml.safe_load(path.read_text(encoding="utf-8"))
    except OSError as error:
        raise SuiteError("{}: cannot read: {}".format(path, error.strerror or error)) from None
    except yaml.YAMLError as error:
        raise SuiteError("{}: not valid YAML: {}".format(label, " ".join(str(error).split()))) from None
    return parse_suite(data, path)


def parse_suite(data, path) -> Suite:
    """Validate already-parsed YAML `data` (from the file at `path`, named in errors)."""
    path = Path(path)
    label = path.name
    convert = _Converters(label)
    top = _Mapping(label, "", data, SUITE_KEYS)
    name = top.get("suite", lambda v, w: convert.text(v, w, SUITE_NAME, "a suite name (letters, digits, _, -)"),
                   required=True)
    title = top.get("title", convert.text, default=name)
    world = top.get("world", convert.text)
    simulator_args = top.get("simulator_args", lambda v, w: convert.fields(v, w, convert.scalar), default={})
    if simulator_args and world is None:
        top.fail("simulator_args", "needs a world: without one no simulator runs")
    real_time_factor = top.get("real_time_factor", convert.positive, default=DEFAULT_REAL_TIME_FACTOR)
    settle_s = top.get("settle_s", convert.non_negative, default=DEFAULT_SETTLE_S)
    default_timeout_s = top.get("timeout_s", convert.positive, default=DEFAULT_TIMEOUT_S)
    still_timeout_s = top.get("still_timeout_s", convert.positive, default=DEFAULT_STILL_TIMEOUT_S)
    by_type_grace_s = top.get("by_type_grace_s", convert.non_negative, default=DEFAULT_BY_TYPE_GRACE_S)
    services = top.get("services", lambda v, w: _services(convert, v, w, "a service type (package/Type)"),
                       default=())
    actions = top.get("actions", lambda v, w: _services(convert, v, w, "an action type (package/Name)"),
                      default=())
    runs = top.get("runs", lambda v, w: _runs(convert, v, w, world), default=())
    if not services and not actions and not runs:
        top.fail("services", "missing (a suite needs services, actions or runs)")
    taken = [spec.node for spec in services + actions]
    for index, run in enumerate(runs):
        if run.node in taken:
            top.fail("runs[{}].node".format(index), "{} also serves a service or action: a run's node serves "
                                                     "nothing".format(run.node))
    targets = _Targets([service.name for service in services], [action.name for action in actions], world,
                       [run.node for run in runs])
    checks = top.get("checks", lambda v, w: _checks(convert, v, w, targets, default_timeout_s), required=True)
    return Suite(name=name, title=title, path=path, world=world, real_time_factor=real_time_factor,
                 settle_s=float(settle_s),
                 still_timeout_s=still_timeout_s, by_type_grace_s=float(by_type_grace_s), services=services,
                 checks=checks, actions=actions, simulator_args=tuple(simulator_args.items()), runs=runs)


class _Targets(NamedTuple):
    """What checks may refer to: the suite's service and action names, and whether a world (a robot) runs."""

    services: List[str]
    actions: List[str]
    world: Optional[str]
    runs: List[str] = []


def _items(convert, value, where):
    if not isinstance(value, list) or not value:
        convert.fail(where, "expected a non-empty list, got {}".format(_show(value)))
    return [("{}[{}]".format(where, index), item) for index, item in enumerate(value)]


def _file_name(convert, value, where):
    """A node's file name, as services and runs name the student's script."""
    return convert.text(value, where, FILE_NAME, "a file name (no folders)")


def _services(convert, value, where, what) -> Tuple[ServiceSpec, ...]:
    result: List[ServiceSpec] = []
    for item_where, item in _items(convert, value, where):
        entry = _Mapping(convert.file_label, item_where, item, SERVICE_KEYS)
        name = entry.get("name", lambda v, w: convert.text(v, w, SERVICE_NAME, "an absolute ROS name (/a/b)"),
                         required=True)
        srv_type = entry.get("type", lambda v, w: convert.text(v, w, TYPE_NAME, what), required=True)
        node = entry.get("node", lambda v, w: _file_name(convert, v, w), required=True)
        wait_s = entry.get("wait_s", convert.non_negative, default=DEFAULT_WAIT_S)
        if any(service.name == name for service in result):
            convert.fail(entry.where("name"), "{} is listed twice".format(name))
        result.append(ServiceSpec(name, srv_type, float(wait_s), node))
    return tuple(result)


def _runs(convert, value, where, world) -> Tuple[RunSpec, ...]:
    result: List[RunSpec] = []
    for item_where, item in _items(convert, value, where):
        entry = _Mapping(convert.file_label, item_where, item, RUN_KEYS)
        node = entry.get("node", lambda v, w: _file_name(convert, v, w), required=True)
        if any(run.node == node for run in result):
            convert.fail(entry.where("node"), "{} is listed twice".format(node))
        duration_s = entry.get("duration_s", convert.positive, required=True)
        start_s = entry.get("start_s", convert.positive, default=DEFAULT_START_S)
        run_world = entry.get("world", convert.text)
        if world is None:
            convert.fail(item_where, "a run needs a robot: the suite has no world (a run may name another world "
                                     "than the suite's, which the grader then starts for it)")
        args = entry.get("simulator_args", lambda v, w: convert.fields(v, w, convert.scalar))
        result.append(RunSpec(node, float(duration_s), run_world, None if args is None else tuple(args.items()),
                              float(start_s)))
    return tuple(result)


def _reference(convert, value, where, names, what):
    if value not in names:
        convert.fail(where, "{} is not one of the suite's {} ({})".format(_show(value), what, ", ".join(names)
                                                                          or "none"))
    return value


def _checks(convert, value, where, targets, default_timeout_s) -> Tuple[CheckSpec, ...]:
    result: List[CheckSpec] = []
    for item_where, item in _items(convert, value, where):
        is_action = isinstance(item, dict) and "action" in item
        is_run = isinstance(item, dict) and "run" in item
        entry = _Mapping(convert.file_label, item_where, item, RUN_CHECK_KEYS if is_run
                         else ACTION_CHECK_KEYS if is_action else SERVICE_CHECK_KEYS)
        check_id = entry.get("id", lambda v, w: convert.text(v, w, CHECK_ID, "a check id (a-z, 0-9, _)"),
                             required=True)
        if any(check.id == check_id for check in result):
            convert.fail(entry.where("id"), "check id {} is used twice".format(check_id))
        title = entry.get("title", convert.text, required=True)
        kind = entry.get("kind", lambda v, w: convert.choice(v, w, CHECK_KINDS), default=REQUIRED)
        weight = entry.get("weight", convert.non_negative, required=kind == REQUIRED, default=0)
        if is_run:
            run = entry.get("run", lambda v, w: _reference(convert, v, w, targets.runs, "runs"))
            expect = entry.get("expect", lambda v, w: _run_expectation(convert, v, w), required=True)
            result.append(CheckSpec(check_id, title, weight, None, None, 0.0, expect, kind=kind, run=run))
            continue
        timeout_s = float(entry.get("timeout_s", convert.positive, default=default_timeout_s))
        if is_action:
            action = entry.get("action", lambda v, w: _reference(convert, v, w, targets.actions, "actions"))
            goal = entry.get("goal", lambda v, w: convert.fields(v, w, convert.scalar), default={})
            cancel_after_s = entry.get("cancel_after_s", convert.positive)
            expect = entry.get("expect", lambda v, w: _action_expectation(convert, v, w, targets.world),
                               default=_action_expectation(convert))
            result.append(CheckSpec(check_id, title, weight, None, None, timeout_s, expect, action=action, goal=goal,
                                    cancel_after_s=None if cancel_after_s is None else float(cancel_after_s),
                                    kind=kind))
            continue
        service = entry.get("service", lambda v, w: _reference(convert, v, w, targets.services, "services"),
                            required=True)
        request = entry.get("request", lambda v, w: convert.fields(v, w, convert.scalar), default={})
        expect = entry.get("expect", lambda v, w: _expectation(convert, v, w, targets.world),
                           default=_expectation(convert))
        result.append(CheckSpec(check_id, title, weight, service, request, timeout_s, expect, kind=kind))
    return tuple(result)


def _expectation(convert, value=None, where="expect", world=None) -> Expectation:
    if value is None:
        return Expectation({}, {}, None, None)
    mapping = _Mapping(convert.file_label, where, value, EXPECT_KEYS)
    _needs_robot(mapping, world)
    reply = mapping.get("reply", lambda v, w: convert.fields(v, w, convert.scalar), default={})
    matches = mapping.get("reply_matches", lambda v, w: convert.fields(v, w, convert.regex), default={})
    refused = mapping.get("refused", convert.boolean, default=False)
    if refused and (reply or matches):
        mapping.fail(mapping.where("refused"), "a refused call has no reply to compare with reply/reply_matches")
    motion = mapping.get("motion", lambda v, w: _motion(convert, v, w))
    front = mapping.get("front_distance_m", convert.range)
    return Expectation(reply, matches, motion, front, refused)


def _needs_robot(mapping, world):
    for robot_key in ROBOT_EXPECT_KEYS:
        if robot_key in mapping.data and world is None:
            mapping.fail(mapping.where(robot_key), "needs a robot: the suite has no world")


def _action_expectation(convert, value=None, where="expect", world=None) -> ActionExpectation:
    if value is None:
        return ActionExpectation((), {}, {}, {}, None, None, {}, None, (), None, None)
    mapping = _Mapping(convert.file_label, where, value, ACTION_EXPECT_KEYS)
    _needs_robot(mapping, world)
    states = mapping.get("state", lambda v, w: _states(convert, v, w), default=())
    result = mapping.get("result", lambda v, w: convert.fields(v, w, convert.scalar), default={})
    matches = mapping.get("result_matches", lambda v, w: convert.fields(v, w, convert.regex), default={})
    feedback = mapping.get("feedback", lambda v, w: convert.fields(v, w, lambda i, iw: _sequence(convert, i, iw)),
                           default={})
    return ActionExpectation(
        states, result, matches, feedback, mapping.get("duration_s", convert.range),
        mapping.get("cancel_to_end_s", convert.range),
        result_ranges=mapping.get("result_ranges", lambda v, w: convert.fields(v, w, convert.range), default={}),
        feedback_count=mapping.get("feedback_count", convert.range),
        feedback_rising=mapping.get("feedback_rising", lambda v, w: _field_names(convert, v, w), default=()),
        motion=mapping.get("motion", lambda v, w: _motion(convert, v, w)),
        front_distance_m=mapping.get("front_distance_m", convert.range),
        images=mapping.get("images", lambda v, w: _images(convert, v, w)))


def _point(convert, value, where) -> Tuple[float, float]:
    if not isinstance(value, list) or len(value) != 2:
        convert.fail(where, "expected a point [x, y] in m, got {}".format(_show(value)))
    return tuple(float(convert.number(item, "{}[{}]".format(where, index))) for index, item in enumerate(value))


def _stops_facing(convert, value, where) -> StopsFacing:
    mapping = _Mapping(convert.file_label, where, value, STOPS_FACING_KEYS)
    landmarks = mapping.get("landmarks", lambda v, w: convert.fields(v, w, lambda i, iw: _point(convert, i, iw)),
                            required=True)
    faces = mapping.get("faces", lambda v, w: _field_names(convert, v, w), required=True)
    for index, name in enumerate(faces):
        if name not in landmarks:
            mapping.fail("{}[{}]".format(mapping.where("faces"), index),
                         "{} is not one of the landmarks ({})".format(_show(name), ", ".join(landmarks)))
    return StopsFacing(faces, landmarks, float(mapping.get("tolerance_deg", convert.positive, required=True)),
                       float(mapping.get("still_s", convert.positive, required=True)))


def _line(convert, value, where) -> LineExpectation:
    mapping = _Mapping(convert.file_label, where, value, LINE_KEYS)
    points = mapping.get("points", lambda v, w: _items(convert, v, w), required=True)
    if len(points) < 4 or (len(points) - 1) % 3:
        mapping.fail(mapping.where("points"), "expected a start point and 3 more per cubic Bezier, got {} "
                                              "points".format(len(points)))
    return LineExpectation(tuple(_point(convert, item, item_where) for item_where, item in points),
                           float(mapping.get("leave_m", convert.positive, required=True)),
                           progress_m=mapping.get("progress_m", convert.range),
                           mean_distance_m=mapping.get("mean_distance_m", convert.range),
                           max_distance_m=mapping.get("max_distance_m", convert.range))


RUN_EXPECT_PARSERS = {"stops_facing": _stops_facing, "line": _line}   # RunExpectation's fields, each a kind


def _run_expectation(convert, value, where) -> RunExpectation:
    mapping = _Mapping(convert.file_label, where, value, tuple(RUN_EXPECT_PARSERS))
    if not mapping.data:
        mapping.fail(where, "expected one of {}".format(", ".join(RUN_EXPECT_PARSERS)))
    return RunExpectation(**{key: mapping.get(key, lambda v, w, parse=parse: parse(convert, v, w))
                             for key, parse in RUN_EXPECT_PARSERS.items()})


def _images(convert, value, where) -> ImagesExpectation:
    mapping = _Mapping(convert.file_label, where, value, IMAGES_KEYS)
    field = mapping.get("path_field", lambda v, w: convert.text(v, w, FIELD_NAME, "a field name"), required=True)
    count = mapping.get("count", lambda v, w: convert.number(v, w, minimum=0), required=True)
    if not float(count).is_integer():
        mapping.fail(mapping.where("count"), "expected a whole number of images, got {}".format(_show(count)))
    return ImagesExpectation(field, int(count))


def _field_names(convert, value, where) -> Tuple[str, ...]:
    if not isinstance(value, list) or not value:
        convert.fail(where, "expected a non-empty list of field names, got {}".format(_show(value)))
    return tuple(convert.text(item, "{}[{}]".format(where, index), FIELD_NAME, "a field name")
                 for index, item in enumerate(value))


def _states(convert, value, where) -> Tuple[str, ...]:
    names = [value] if isinstance(value, str) else value
    if not isinstance(names, list) or not names:
        convert.fail(where, "expected a goal state or a list of them, got {}".format(_show(value)))
    for index, name in enumerate(names):
        if name not in GOAL_STATES:
            convert.fail(where if isinstance(value, str) else "{}[{}]".format(where, index),
                         "{} is not a goal state ({})".format(_show(name), ", ".join(GOAL_STATES)))
    return tuple(names)


def _sequence(convert, value, where) -> Tuple[Any, ...]:
    if not isinstance(value, list):
        convert.fail(where, "expected a list of values, got {}".format(_show(value)))
    return tuple(convert.scalar(item, "{}[{}]".format(where, index)) for index, item in enumerate(value))


def _motion(convert, value, where) -> MotionExpectation:
    mapping = _Mapping(convert.file_label, where, value, MotionExpectation._fields)
    return MotionExpectation(
        forward_m=mapping.get("forward_m", convert.range),
        lateral_max_m=mapping.get("lateral_max_m", convert.non_negative),
        turn_deg=mapping.get("turn_deg", convert.range),
        turn_max_deg=mapping.get("turn_max_deg", convert.non_negative),
        duration_s=mapping.get("duration_s", convert.range),
        excursion_max_m=mapping.get("excursion_max_m", convert.non_negative),
        still_at_end=mapping.get("still_at_end", convert.boolean),
        mean_speed_mps=mapping.get("mean_speed_mps", convert.range),
    )


def resolve_suite(name_or_path, suites_dir) -> Path:
    """The suite file for `name_or_path`: an existing path (or anything with a / or ending in .yaml) is a path,
    anything else a name looked up as <suites_dir>/<name>.yaml. SuiteError listing the known names if missing."""
    text = str(name_or_path)
    candidate = Path(text)
    if "/" in text or text.endswith(SUITE_SUFFIX) or candidate.is_file():
        if not candidate.is_file():
            raise SuiteError("{}: no such suite file".format(text))
        return candidate
    if not SUITE_NAME.match(text):
        raise SuiteError("{!r} is neither a suite name nor a suite file".format(text))
    path = Path(suites_dir) / (text + SUITE_SUFFIX)
    if not path.is_file():
        known = sorted(p.stem for p in Path(suites_dir).glob("*" + SUITE_SUFFIX))
        raise SuiteError("no suite named {!r} in {} (known: {})".format(text, suites_dir, ", ".join(known) or "none"))
    return path
