"""Grading one submission, from its source folder to its result: everything that happens inside its sandbox.

The order is a marker's: copy the package into a fresh catkin workspace, `chmod +x` its Python files (as the course
tells students to), build it with catkin_make on top of the lab, start roscore and, when the suite has a world,
tb3_sim (trusted, in the box's own loopback-only network, serving its ground truth on a private socket in the box's
root-only folder, which the student's processes cannot see: lab_grader.checks.ground_truth), start the student's
nodes the way the course says (`rosrun <package> <file>`: the file rosrun would run, which the grader has found, run
directly: `rosrun()`), then run the suite's checks (what `rosrun lab_grader
run_checks` runs, as `python3 -m lab_grader.checks.runner`: trusted, so rosrun's package search, four catkin_find
runs, is not needed) and read their JSON. One check runner serves every exercise of a submission (`run_checks
--serve`: an exercise per line on its stdin), started while the package builds (it waits for roscore and the
simulator itself, and creates a file once they answer: the student's first node starts then); only a runner stopped
because the student's node died, or one that overran, is replaced for the next exercise. A build that fails, a
node that is missing or dies, a check runner that overruns: each is recorded with its evidence (the tail of the
log) and the submission gets the checks' verdicts as far as they got; the batch goes on.

A run (a node that serves nothing but drives the robot: Part 6) is graded so: the runner resets the robot, waits
until it rests and creates the exercise's ready file; only then does the grader start the student's node (found by
the course's file name, else by a script whose name shares a word with it), and the runner records the robot for
the run's duration. A run's node that ends by itself with exit status 0 (its job done) has not crashed; the
runner is told (the exercise's ended file) and ends the recording once the robot has rested for a while. An exercise
in another world (or with other simulator arguments) than the one running gets a simulator of its own: the running
one is stopped, with the check runner that was connected to it, and the next starts in its place.

Logs are written by the grader outside the student's workspace, under the submission's output folder.
"""
import json
import os
import re
import shlex
import threading
import time
from pathlib import Path
from typing import Dict, List, Optional

from lab_grader.checks.verdicts import CRASHED, ERROR, PASS, CheckResult, Verdict, one_line, tidy
from lab_grader.html_report import report_html
from lab_grader.node_logs import build_errors, traceback_of
from lab_grader.sandbox import STUDENT_UID_BASE, Limits, SubmissionSandbox
from lab_grader.submissions import read_package_name
from lab_grader.worlds import launch_argument

BUILD_TIMEOUT_S = 300.0
SIMULATOR_START_S = 60.0
SIMULATOR_READY_SERVICE = "/gazebo/reset_world"
MASTER_READY_SERVICE = "/rosout/get_loggers"    # roscore's rosout node is up: the master answers
CHECKS_TIMEOUT_S = 600.0      # one exercise's checks
READY_TIMEOUT_S = 60.0        # a run's robot must be reset and at rest within this (the runner says so)
RUNNER_EXIT_S = 10.0          # the check runner ends this soon after the end of its input (it leaves the graph)
TRY_SCRIPT_S = 60.0            # a script tried for an exercise must offer its service (or action) within this ...
NODE_UP_GRACE_S = 5.0          # ... or within this once it has called init_node
POLL_S = 0.05                  # how often the grader looks at a node, the check runner and find_server
SCRIPT_SCAN_BYTES = 256 * 1024  # a script is a node when init_node appears this early in it
LOG_TAIL_CHARS = 3000
BUILD_LOG_CHARS = 200000       # how much of the build log is searched for catkin's error lines
ROS_PORT = 11311
GROUND_TRUTH_SOCKET = "truth.sock"     # in the box's trusted folder (a Unix socket path must be short)
STARTED_FILE = "ros-started"   # in the box's trusted folder: the first check runner creates it once roscore (and
                               # the simulator) answer
RESULT_FILE = "result.json"
REPORT_FILE = "report.html"
STUDENT_LIMITS = Limits(cpu_s=600, processes=512, output_bytes=1024 * 1024, wall_s=BUILD_TIMEOUT_S)


def log_tail(path: Path, chars=LOG_TAIL_CHARS) -> str:
    try:
        text = Path(path).read_text(errors="replace")
    except OSError:
        return ""
    return text[-chars:]


def find_node(submission, file_name: str):
    """(package name, path) of the first `file_name` in the submission's packages (in src/, scripts/, nodes/ or
    anywhere in the package, sorted for the same answer every time), or None. Package names are read as the intake
    read them (submissions.read_package_name: the untrusted package.xml size-bounded first)."""
    source_dir = Path(submission.source_dir)
    for package_xml in sorted(source_dir.rglob("package.xml")):
        package_dir = package_xml.parent
        for candidate in sorted(package_dir.rglob(file_name)):
            if candidate.is_file() and "build" not in candidate.relative_to(package_dir).parts[:1]:
                return read_package_name(submission.student_id, package_xml, source_dir), candidate
    return None


def node_candidates(submission, course_name: str):
    """[(package name, path)] of every script in the submission's packages that starts a ROS node (a .py file that
    calls init_node, not setup.py or __init__.py), those sharing a word with `course_name` first
    (approach_object_server.py for approach_server.py), then by path."""
    source_dir = Path(submission.source_dir)
    words = set(re.findall(r"[a-z0-9]+", course_name.lower())) - {"py", "server", "node"}
    found = []
    for package_xml in sorted(source_dir.rglob("package.xml")):
        package_dir = package_xml.parent
        package = None
        for path in sorted(package_dir.rglob("*.py")):
            if (path.name in ("setup.py", "__init__.py") or path.is_symlink() or not path.is_file()
                    or "build" in path.relative_to(package_dir).parts[:1]):
                continue
            with open(path, "rb") as source:
                if b"init_node" not in source.read(SCRIPT_SCAN_BYTES):
                    continue
            package = package or read_package_name(submission.student_id, package_xml, source_dir)
            found.append((package, path))
    return sorted(found, key=lambda item: (not words & set(re.findall(r"[a-z0-9]+", item[1].name.lower())),
                                           str(item[1])))


def run_candidate(submission, course_name: str):
    """(package, path) for a run whose course file `course_name` is missing: the first script that starts a node and
    shares a word with the course's name (colour_search_node.py for colour_search.py), or None. A run serves
    nothing the grader could recognise it by, so the name is all there is."""
    words = set(re.findall(r"[a-z0-9]+", course_name.lower())) - {"py", "server", "node"}
    return next((candidate for candidate in node_candidates(submission, course_name)
                 if words & set(re.findall(r"[a-z0-9]+", candidate[1].name.lower()))), None)


def ros_environment(base_env: Dict[str, str]) -> Dict[str, str]:
    """The lab's ROS environment, bound to the box's own master on loopback."""
    env = dict(base_env, ROS_MASTER_URI="http://localhost:{}".format(ROS_PORT), ROS_HOSTNAME="localhost")
    env.pop("ROS_IP", None)
    return env


def headless(env: Dict[str, str]) -> Dict[str, str]:
    """`env` for the student's processes: no X display (the box has none), and Qt's offscreen platform, so that
    cv2.imshow and cv2.waitKey, which the course's vision templates call on every frame, work and show nothing
    instead of aborting the node ("could not connect to display")."""
    env = dict(env, QT_QPA_PLATFORM="offscreen")
    env.pop("DISPLAY", None)
    return env


def overlay(command: str) -> List[str]:
    """A shell command run after sourcing the student's overlay workspace (devel/setup.bash)."""
    return ["bash", "-c", "source devel/setup.bash && " + command]


def rosrun(submission, path: Path) -> List[str]:
    """The command that starts the student's node file `path` (in their source folder) as `rosrun <package> <file>`
    does: the file itself, executed from its place in the box's workspace (src/...) after sourcing the overlay. The
    grader has already found the file (find_node, node_candidates), so rosrun's own search is skipped: two
    catkin_find runs and a rospack find: about 1 s of every start at load 9 (0.5 s a catkin_find), 2-3 s at load 20."""
    return overlay("exec " + shlex.quote(str(Path("src") / path.relative_to(submission.source_dir))))


class SubmissionGrader:
    """Grades submissions one at a time in one sandbox slot. `suite` is a loaded suite (lab_grader.suite_file)."""

    def __init__(self, suite, work_root: Path, lab_root: Path, slot: int, base_env: Dict[str, str],
                 real_time_factor: Optional[float] = None, limits: Limits = STUDENT_LIMITS):
        self.suite = suite
        self.work_root = Path(work_root)
        self.lab_root = Path(lab_root)
        self.slot = slot
        self.env = ros_environment(base_env)
        self.real_time_factor = suite.real_time_factor if real_time_factor is None else real_time_factor
        self.limits = limits

    def grade(self, submission, out_dir: Path, on_stage=lambda what, checks_log=None: None) -> dict:
        """Grade `submission` (lab_grader.submissions.Submission); writes out_dir/result.json and the logs, and
        returns the result. `on_stage(what, checks_log=None)` hears each stage as it starts (for a progress line)."""
        out_dir = Path(out_dir)
        out_dir.mkdir(parents=True, exist_ok=True)
        started = time.monotonic()
        result = {"student": submission.student_id, "suite": self.suite.name, "packages": list(submission.packages),
                  "real_time_factor": self.real_time_factor, "sandbox_uid": STUDENT_UID_BASE + self.slot,
                  "build": None, "nodes": [], "checks": [], "services": {}, "score": 0.0,
                  "max_score": self.suite.max_score, "problems": []}
        stages = [("sandbox", started)]

        def stage(what, checks_log=None):
            stages.append((what, time.monotonic()))
            on_stage(what, checks_log)

        try:
            with SubmissionSandbox(self.work_root, self.slot, self.lab_root, self.limits) as box:
                self._grade_in(box, submission, out_dir, result, stage)
                stages.append(("closing", time.monotonic()))
        except Exception as error:   # noqa: BLE001 - the batch goes on; the reason is in the result
            result["problems"].append("grading stopped: {}".format(error))
        finished = time.monotonic()
        result["duration_s"] = round(finished - started, 1)
        # Wall seconds per stage (sandbox set-up, copying, building, starting, checks, closing): where time goes.
        result["stage_s"] = {what: round(end - begin, 1) for (what, begin), (_, end)
                             in zip(stages, stages[1:] + [(None, finished)])}
        try:
            (out_dir / REPORT_FILE).write_text(report_html(result, self._worlds()))
        except Exception as error:   # noqa: BLE001 - a picture that cannot be drawn must not lose the grades
            result["problems"].append("the HTML report could not be written: {}".format(error))
        write_json(out_dir / RESULT_FILE, result)
        return result

    def _grade_in(self, box, submission, out_dir, result, on_stage):
        on_stage("copying")
        box.copy_into_workspace(submission.source_dir, "src")
        env = headless(box.student_env(self.env))
        box.run_student(["find", "src", "-name", "*.py", "-exec", "chmod", "+x", "{}", "+"], env,
                        out_dir / "chmod.log", timeout_s=30)
        # roscore and the simulator start while the package builds (they do not need it): the two start-ups overlap
        # instead of adding up. A build that fails has cost a simulator start-up for nothing.
        on_stage("building (and starting {})".format(self._ros_what()))
        # So does the first check runner: it waits for them itself, then connects (its imports, init_node and the
        # ground-truth connection are made during the build) and says so by creating `started`.
        truth_socket = box.trusted_dir / GROUND_TRUTH_SOCKET
        self._simulator = None
        ready_service, startup_log = self._start_ros(box, out_dir, truth_socket, self.suite.exercises()[0])
        started = box.trusted_dir / STARTED_FILE
        runner = self._start_runner(box, out_dir, truth_socket, 1, ["--wait-service", ready_service, "--wait-s",
                                                                    str(SIMULATOR_START_S), "--started", str(started)])
        build = box.run_student(["catkin_make"], env, out_dir / "build.log", timeout_s=BUILD_TIMEOUT_S)
        result["build"] = {"ok": build.ok, "stopped": build.stop_reason, "log_tail": None if build.ok
                           else log_tail(out_dir / "build.log"),
                           "errors": [] if build.ok else build_errors(log_tail(out_dir / "build.log", BUILD_LOG_CHARS))}
        if not build.ok:
            result["problems"].append("the package does not build (catkin_make)")
            return
        on_stage("starting {}".format(self._ros_what()))
        deadline = time.monotonic() + SIMULATOR_START_S + RUNNER_EXIT_S    # the runner gives up after the first
        while not started.exists() and runner.running() and time.monotonic() < deadline:
            time.sleep(POLL_S)
        if not started.exists():
            result["problems"].append("{} did not start: {}".format(self._ros_what(), log_tail(startup_log, 500)))
            return
        result.update(combine(self.suite, self._grade_exercises(box, submission, env, out_dir, result, on_stage,
                                                                truth_socket, runner)))

    def _grade_exercises(self, box, submission, env, out_dir, result, on_stage, truth_socket, runner):
        """Grade the exercises one after the other, each with its node alone, through one check runner (`runner`,
        connected to the running simulator, to begin with); the nodes' records go into result["nodes"] and the
        problems into result["problems"]. Returns {exercise's file: its results}."""
        parts = {}
        exercises = self.suite.exercises()
        runner_from = 1               # the exercise the running runner started at (its log's name)
        stopping = Stopping(None)     # the previous exercise's node, stopped while the next one starts

        def close_runner():
            runner.close_input()
            runner.wait(RUNNER_EXIT_S)

        try:
            for number, exercise in enumerate(exercises, start=1):
                if self._simulator is not None and self._simulator[0] != self._simulator_key(exercise):
                    on_stage("exercise {}/{} ({}): starting its world".format(number, len(exercises), exercise.node))
                    stopping.join()
                    if runner is not None:
                        close_runner()       # connected to the simulator about to stop
                        runner = None
                    problem = self._switch_simulator(box, out_dir, truth_socket, exercise)
                    if problem is not None:
                        result["problems"].append(problem)
                        parts[exercise.node] = not_run(self.suite, exercise, {"problem": problem})
                        continue
                if runner is None:
                    runner, runner_from = self._start_runner(box, out_dir, truth_socket, number), number
                checks_log = out_dir / "checks-{}.log".format(number)
                checks_file = out_dir / "checks-{}.json".format(number)
                checks_file.unlink(missing_ok=True)   # an earlier grading's, in the same output folder
                command = {"exercise": exercise.node, "out": str(checks_file), "log": str(checks_log)}
                on_stage("exercise {}/{} ({}): finding its node".format(number, len(exercises), exercise.node))
                if exercise.run is not None or find_node(submission, exercise.node) is None:
                    stopping.join()   # a script tried by type could be taken for the previous node's service
                if exercise.run is None:
                    node, server = self._start_server(box, submission, exercise, env, out_dir, number,
                                                      served=[node["file"] for node in result["nodes"]
                                                              if node["file"]])
                else:
                    node, server = self._find_run_node(box, submission, exercise, env, out_dir)
                result["nodes"].append(node)
                if server is None:
                    parts[exercise.node] = not_run(self.suite, exercise, node)
                    continue
                stopping.join()                 # the exercise's node runs alone during its checks
                checks_log.write_text("")       # the runner appends this exercise's lines
                on_stage("exercise {}/{} ({}): checks".format(number, len(exercises), exercise.node), checks_log)
                if exercise.run is None:
                    ended = watch_checks(runner, server, json.dumps(command), checks_file)
                else:
                    ready = out_dir / "ready-{}".format(number)
                    ready.unlink(missing_ok=True)
                    node_ended = out_dir / "ended-{}".format(number)
                    node_ended.unlink(missing_ok=True)
                    ended, server = self._watch_run(
                        runner, json.dumps(dict(command, ready=str(ready), ended=str(node_ended))), ready, node_ended,
                        checks_file, lambda start_node=server: start_node(number))
                crashed = server is not None and not server.running() and (exercise.run is None
                                                                             or not server.wait(0).ok)
                node.update(running_at_end=server is not None and server.running(),
                            **(crash_report(server.log_path) if crashed else {}))
                stopping = Stopping(server)
                checks = read_json(checks_file)
                if ended is not None:
                    runner = None     # it ended or was stopped: the next exercise starts another
                if checks is None:
                    why = ("its results file is unreadable" if ended is None
                           else ended.stop_reason or "exit {}".format(ended.returncode))
                    tail = log_tail(checks_log, 500) or log_tail(runner_log(out_dir, runner_from), 500)
                    result["problems"].append("the checks of {} did not finish ({}): {}".format(exercise.node, why,
                                                                                                  tail))
                    parts[exercise.node] = not_run(self.suite, exercise, node, "the checks did not finish")
                    continue
                parts[exercise.node] = checks_as_crashed(checks, node) if crashed else checks
        finally:
            if runner is not None:
                close_runner()
            stopping.join()
        return parts

    def _start_runner(self, box, out_dir, truth_socket, number, wait=()):
        """Start a check runner serving this suite's exercises (`--serve`), its log named after the exercise
        `number` it starts at; `wait`: its --wait-service arguments, if any."""
        return box.start_trusted(["python3", "-m", "lab_grader.checks.runner", "--suite", str(self.suite.path),
                                  "--serve", "--ground-truth", str(truth_socket), "--student-home", str(box.workspace),
                                  *wait], self.env, runner_log(out_dir, number), commands=True)

    def _find_run_node(self, box, submission, exercise, env, out_dir):
        """(the node's record, a function that starts it: number -> SandboxProcess) for a run, or (record, None):
        the course's file name, else a script named like it (run_candidate)."""
        node = {"exercise": exercise.node, "serves": [], "file": None, "package": None, "found_by": None,
                "tried": [], "running_at_end": False, "problem": None, "crashed": False, "traceback": None,
                "log_tail": None}
        found, how = find_node(submission, exercise.node), "the course's file name"
        if found is None:
            found, how = run_candidate(submission, exercise.node), "a script named like the course's file"
        if found is None:
            node["problem"] = "no file named {} and no script whose name shares a word with it".format(exercise.node)
            return node, None
        package, path = found
        node.update(file=str(path.relative_to(submission.source_dir)), package=package, found_by=how)
        node["tried"].append(node["file"])

        def start(number):
            return box.start_student(rosrun(submission, path), env,
                                     out_dir / "node-{}-{}.log".format(number, path.name))
        return node, start

    @staticmethod
    def _watch_run(runner, command, ready, node_ended, checks_file, start):
        """Give the runner a run's `command`, start the node (`start()`) once the runner has created `ready` (the
        robot reset and at rest), and wait for `checks_file` as watch_checks does; the node may end by itself
        meanwhile (its job done: the file `node_ended` then tells the runner, which ends the recording once the
        robot rests). Returns (watch_checks's answer, the node's SandboxProcess or None)."""
        if not runner.send_line(command):
            return runner.wait(RUNNER_EXIT_S), None
        deadline = time.monotonic() + READY_TIMEOUT_S
        while not ready.exists():
            if checks_file.exists():
                return None, None     # the runner could not prepare the robot: its results say why
            if not runner.running() or time.monotonic() > deadline:
                return runner.wait(0), None
            time.sleep(POLL_S)
        server = start()
        return wait_for_checks(runner, server, checks_file, ended=node_ended), server
    def _worlds(self):
        """[(world, the ids of the checks graded in it)] in the suite's order, for the report's pictures."""
        worlds = {}
        for exercise in self.suite.exercises():
            world = self.suite.world_of(exercise)
            if world is not None:
                worlds.setdefault(world, []).extend(exercise.check_ids)
        return list(worlds.items())

    def _ros_what(self):
        return "roscore" if self.suite.world_of(self.suite.exercises()[0]) is None else "the simulator"

    def _start_ros(self, box, out_dir, truth_socket, exercise):
        """Start roscore and, when `exercise` has a world, tb3_sim serving its ground truth on `truth_socket`.
        Returns (the service that says they are up, the log that says why not)."""
        box.start_trusted(["roscore", "-p", str(ROS_PORT)], self.env, out_dir / "roscore.log")
        if self.suite.world_of(exercise) is None:
            return MASTER_READY_SERVICE, out_dir / "roscore.log"
        return SIMULATOR_READY_SERVICE, self._start_simulator(box, out_dir, truth_socket, exercise)

    def _simulator_key(self, exercise):
        return self.suite.world_of(exercise), tuple(self.suite.launch_args(exercise))

    def _start_simulator(self, box, out_dir, truth_socket, exercise):
        """Start tb3_sim in `exercise`'s world with its arguments; returns its log."""
        world, args = self._simulator_key(exercise)
        log = out_dir / ("simulator.log" if self._simulator is None else "simulator-{}.log".format(exercise.node))
        process = box.start_trusted(["roslaunch", "--wait", "tb3_sim", "tb3_sim.launch", "gui:=false",
                                     "world:=" + launch_argument(world),
                                     "real_time_factor:={:g}".format(self.real_time_factor),
                                     "ground_truth_socket:={}".format(truth_socket)] + list(args),
                                    self.env, log)
        self._simulator = (self._simulator_key(exercise), process)
        return log

    def _switch_simulator(self, box, out_dir, truth_socket, exercise):
        """Make sure the simulator runs `exercise`'s world and arguments: stop another and start this one. Returns
        None when it runs, else why not."""
        if self._simulator is None or self._simulator[0] == self._simulator_key(exercise):
            return None
        self._simulator[1].stop()
        log = self._start_simulator(box, out_dir, truth_socket, exercise)
        ready = box.run_trusted(["python3", "-m", "lab_grader.wait_service", SIMULATOR_READY_SERVICE,
                                 str(SIMULATOR_START_S)], self.env, out_dir / "startup_wait.log",
                                timeout_s=SIMULATOR_START_S + 10)
        return None if ready.ok else "the simulator did not start: {}".format(log_tail(log, 500))

    def _start_server(self, box, submission, exercise, env, out_dir, number, served=()):
        """Start the node that serves `exercise`, alone: the course's file when the submission has one (the check
        runner then finds its services itself, and watch_checks notices if it dies), else each of its scripts in
        turn (a file named like the course's first, the `served` files, which served earlier exercises, last) until
        one offers the exercise's service or action by type (lab_grader.find_server). Returns (the node's record for
        the report, its SandboxProcess or None)."""
        specs = (["service:{}:{}".format(spec.name, spec.type) for spec in exercise.services]
                 + ["action:{}:{}".format(spec.name, spec.type) for spec in exercise.actions])
        node = {"exercise": exercise.node, "serves": [spec.name for spec in exercise.services + exercise.actions],
                "file": None, "package": None, "found_by": None, "tried": [], "running_at_end": False,
                "problem": None, "crashed": False, "traceback": None, "log_tail": None}

        def start(package, path):
            relative = str(path.relative_to(submission.source_dir))
            node["tried"].append(relative)
            node.update(file=relative, package=package)
            log = out_dir / "node-{}-{}.log".format(number, path.name)
            return box.start_student(rosrun(submission, path), env, log), log

        course = find_node(submission, exercise.node)
        if course is not None:
            node["found_by"] = "the course's file name"
            return node, start(*course)[0]
        candidates = sorted(node_candidates(submission, exercise.node),
                            key=lambda candidate: str(candidate[1].relative_to(submission.source_dir)) in served)
        for package, path in candidates:
            process, log = start(package, path)
            finder = box.start_trusted(["python3", "-m", "lab_grader.find_server", "--any", "--timeout",
                                        "{:g}".format(TRY_SCRIPT_S), "--give-up", "{:g}".format(NODE_UP_GRACE_S)]
                                       + specs, self.env,
                                       out_dir / "find-{}.log".format(number))
            while finder.running() and process.running():
                time.sleep(POLL_S)
            offered = process.running() and finder.wait(POLL_S).returncode == 0
            finder.kill()
            if offered:
                node["found_by"] = "found by trying each script"
                return node, process
            if not process.running():
                node["tried"][-1] += " (exited: {})".format(crash_report(log)["crash"])
            process.stop()
        node.update(file=None, package=None, problem=(
            "no file named {}, and none of the {} scripts tried offers {}".format(
                exercise.node, len(candidates), " or ".join(specs)) if candidates
            else "no file named {} and no other script in the submission".format(exercise.node)))
        return node, None


class Stopping:
    """A student's node being stopped (SIGINT, then SIGKILL after a grace: SandboxProcess.stop) on a thread of its
    own, so that the next exercise's node starts meanwhile: a rospy node takes 0.5 s to leave the graph on an idle
    machine and 2-3 s on a loaded one, and the next node as long to start. `join()` waits until it has ended; the
    grader joins before the next exercise's checks (each node runs alone during its checks), before trying scripts
    for the next exercise and before switching worlds. `Stopping(None)` has nothing to stop."""

    def __init__(self, process):
        self._thread = None
        if process is not None:
            self._thread = threading.Thread(target=process.stop, name="stop-node", daemon=True)
            self._thread.start()

    def join(self):
        if self._thread is not None:
            self._thread.join()


def watch_checks(runner, server, command, checks_file):
    """Give the serving check runner `runner` (a SandboxProcess) its next exercise, `command`, and wait until it has
    written `checks_file` (wait_for_checks). Returns None while the runner serves on, else its RunResult (it ended,
    or was stopped)."""
    if not runner.send_line(command):
        return runner.wait(RUNNER_EXIT_S)
    return wait_for_checks(runner, server, checks_file)


def wait_for_checks(runner, server, checks_file, ended=None):
    """Wait until the runner has written `checks_file`, at most CHECKS_TIMEOUT_S. If the student's node `server`
    exits meanwhile, stop the runner at once (SIGINT: it writes the results it has, the rest "not run"), unless
    `ended` is given and the node exited with status 0 (a run's node whose job is done): then create the file
    `ended`, which tells the runner. Past the deadline, kill the runner. Returns None while the runner serves on,
    else its RunResult (it ended, or was stopped)."""
    deadline = time.monotonic() + CHECKS_TIMEOUT_S
    while not checks_file.exists():
        if not runner.running():
            return runner.wait(0)
        if not server.running():
            if ended is None or not server.wait(0).ok:
                return runner.stop()
            ended.touch()
        if time.monotonic() > deadline:
            return runner.wait(0)
        time.sleep(POLL_S)
    return None


def runner_log(out_dir: Path, number: int) -> Path:
    """The log of the check runner that started at exercise `number`."""
    return out_dir / "checks-runner-{}.log".format(number)


def crash_report(log_path):
    """The node-record fields of a node that exited: crashed, the last traceback line (crash), the traceback and
    the log's end."""
    text = log_tail(log_path)
    last, traceback = traceback_of(text)
    return {"crashed": True, "crash": last or "it exited (no traceback in its log)", "traceback": traceback,
            "log_tail": text}


def not_run(suite, exercise, node, why=None):
    """The results of an exercise whose checks could not run: crashed when its node died, else error."""
    checks = [check for check in suite.checks if check.id in exercise.check_ids]
    if node.get("crashed"):
        verdict = Verdict.crashed("the node {} exited: {}".format(node["file"], node["crash"]))
    else:
        verdict = Verdict.errored("not run: {}".format(why or node["problem"]))
    return {"services": {spec.name: {"expected_type": spec.type, "found": None, "found_by": None, "found_type": None,
                                     "note": node["problem"] or why} for spec in exercise.services + exercise.actions},
            "checks": [CheckResult(check.id, check.title, check.weight, verdict, check.kind).as_json()
                       for check in checks]}


def checks_as_crashed(checks, node):
    """`checks` (one exercise's results) with every error verdict turned into crashed: its node exited meanwhile."""
    reason = "the node {} exited: {}".format(node["file"], node["crash"])
    changed = [dict(check, verdict=CRASHED, reason=one_line(reason if check["reason"].startswith("not run")
                                                            else "{} ({})".format(reason, check["reason"])))
               if check["verdict"] == ERROR else check for check in checks["checks"]]
    return dict(checks, checks=changed)


def combine(suite, parts):
    """One results document's services, checks (in the suite's order), score and max_score from the exercises'."""
    services, by_id = {}, {}
    for part in parts.values():
        services.update(part["services"])
        by_id.update((check["id"], check) for check in part["checks"])
    checks = [by_id[check.id] for check in suite.checks if check.id in by_id]
    points = sum(check["weight"] for check in checks if check["verdict"] == PASS)
    return {"services": services, "checks": checks, "score": tidy(points), "max_score": suite.max_score}


def write_json(path: Path, content) -> None:
    """Write atomically (a temporary file renamed), so a reader never sees half a result."""
    temporary = Path(str(path) + ".tmp")
    temporary.write_text(json.dumps(content, indent=1, sort_keys=True))
    os.replace(temporary, path)


def read_json(path: Path):
    try:
        return json.loads(Path(path).read_text())
    except (OSError, ValueError):
        return None
