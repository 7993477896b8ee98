"""Grading one submission, from its source folder to its result: everything that happens inside its sandbox.

The order is a marker's: copy the package into a fresh catkin workspace, `chmod +x` its Python files (as the course
tells students to), build it with catkin_make on top of the lab, start roscore and, when the suite has a world,
tb3_sim (trusted, in the box's own loopback-only network, serving its ground truth on a private socket in the box's
root-only folder, which the student's processes cannot see: lab_grader.checks.ground_truth), start the student's
nodes the way the course says (`rosrun <package> <file>`), then run the suite's checks (what `rosrun lab_grader
run_checks` runs, as `python3 -m lab_grader.checks.runner`: trusted, so rosrun's package search, four catkin_find
runs, is not needed) and read their JSON. A build that fails, a node that is missing or dies, a check runner that
overruns: each is recorded with its evidence (the tail of the log) and the submission gets the checks' verdicts as
far as they got; the batch goes on.

Logs are written by the grader outside the student's workspace, under the submission's output folder.
"""
import json
import os
import time
from pathlib import Path
from typing import Dict, List, NamedTuple, Optional

from lab_grader.html_report import report_html
from lab_grader.sandbox import STUDENT_UID_BASE, Limits, SubmissionSandbox
from lab_grader.submissions import read_package_name

BUILD_TIMEOUT_S = 300.0
SIMULATOR_START_S = 60.0
SIMULATOR_READY_SERVICE = "/gazebo/reset_world"
MASTER_READY_SERVICE = "/rosout/get_loggers"    # roscore's rosout node is up: the master answers
CHECKS_TIMEOUT_S = 600.0
LOG_TAIL_CHARS = 3000
ROS_PORT = 11311
GROUND_TRUTH_SOCKET = "truth.sock"     # in the box's trusted folder (a Unix socket path must be short)
RESULT_FILE = "result.json"
REPORT_FILE = "report.html"
CHECKS_FILE = "checks.json"
STUDENT_LIMITS = Limits(cpu_s=600, processes=512, output_bytes=1024 * 1024, wall_s=BUILD_TIMEOUT_S)


class NodeStart(NamedTuple):
    """How one node the suite needs was started: `rosrun package file`, or why it could not be."""

    file: str
    package: Optional[str]
    problem: Optional[str]


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


def ros_environment(base_env: Dict[str, str]) -> Dict[str, str]:
    """The lab's ROS environment, bound to the box's own master on loopback."""
    env = dict(base_env, ROS_MASTER_URI="http://localhost:{}".format(ROS_PORT), ROS_HOSTNAME="localhost")
    env.pop("ROS_IP", None)
    return env


def overlay(command: str) -> List[str]:
    """A shell command run after sourcing the student's overlay workspace (devel/setup.bash)."""
    return ["bash", "-c", "source devel/setup.bash && " + command]


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
            (out_dir / REPORT_FILE).write_text(report_html(result, self.suite.world))
        except Exception as error:   # noqa: BLE001 - a picture that cannot be drawn must not lose the grades
            result["problems"].append("the HTML report could not be written: {}".format(error))
        write_json(out_dir / RESULT_FILE, result)
        return result

    def _grade_in(self, box, submission, out_dir, result, on_stage):
        on_stage("copying")
        box.copy_into_workspace(submission.source_dir, "src")
        env = box.student_env(self.env)
        box.run_student(["find", "src", "-name", "*.py", "-exec", "chmod", "+x", "{}", "+"], env,
                        out_dir / "chmod.log", timeout_s=30)
        on_stage("building")
        build = box.run_student(["catkin_make"], env, out_dir / "build.log", timeout_s=BUILD_TIMEOUT_S)
        result["build"] = {"ok": build.ok, "stopped": build.stop_reason, "log_tail": None if build.ok
                           else log_tail(out_dir / "build.log")}
        if not build.ok:
            result["problems"].append("the package does not build (catkin_make)")
            return
        on_stage("starting roscore" if self.suite.world is None else "starting the simulator")
        truth_socket = box.trusted_dir / GROUND_TRUTH_SOCKET
        box.start_trusted(["roscore", "-p", str(ROS_PORT)], self.env, out_dir / "roscore.log")
        if self.suite.world is None:
            ready_service, startup_log, what = MASTER_READY_SERVICE, out_dir / "roscore.log", "roscore"
        else:
            box.start_trusted(["roslaunch", "--wait", "tb3_sim", "tb3_sim.launch", "gui:=false",
                               "world:=" + self.suite.world, "real_time_factor:={:g}".format(self.real_time_factor),
                               "ground_truth_socket:={}".format(truth_socket)],
                              self.env, out_dir / "simulator.log")
            ready_service, startup_log, what = SIMULATOR_READY_SERVICE, out_dir / "simulator.log", "the simulator"
        ready = box.run_trusted(["python3", "-m", "lab_grader.wait_service", ready_service, str(SIMULATOR_START_S)],
                                self.env, out_dir / "startup_wait.log", timeout_s=SIMULATOR_START_S + 10)
        if not ready.ok:
            result["problems"].append("{} did not start: {}".format(what, log_tail(startup_log, 500)))
            return
        on_stage("starting nodes")
        nodes = []
        for file_name in self.suite.nodes:
            found = find_node(submission, file_name)
            if found is None:
                nodes.append(NodeStart(file_name, None, "no file named {} in the submission".format(file_name)))
                continue
            package, _ = found
            log = out_dir / "node-{}.log".format(file_name)
            process = box.start_student(overlay("exec rosrun {} {}".format(package, file_name)), env, log)
            nodes.append((NodeStart(file_name, package, None), process, log))
        # No pause for the nodes to start: the check runner waits for each service itself (the suite's wait_s).
        checks_log = out_dir / "checks.log"
        on_stage("checks", checks_log)
        run = box.run_trusted(["python3", "-m", "lab_grader.checks.runner", "--suite", str(self.suite.path),
                               "--out", str(out_dir / CHECKS_FILE), "--ground-truth", str(truth_socket)],
                              self.env, checks_log, timeout_s=CHECKS_TIMEOUT_S)
        for entry in nodes:
            if isinstance(entry, NodeStart):
                result["nodes"].append(entry._asdict())
                continue
            start, process, log = entry
            died = not process.running()
            result["nodes"].append(dict(start._asdict(), running_at_end=not died,
                                        log_tail=log_tail(log) if died else None))
        checks = read_json(out_dir / CHECKS_FILE)
        if checks is None:
            result["problems"].append("the checks did not finish ({}): {}".format(
                run.stop_reason or "exit {}".format(run.returncode), log_tail(checks_log, 500)))
            return
        result.update(checks=checks["checks"], services=checks["services"], score=checks["score"],
                      max_score=checks["max_score"])


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
