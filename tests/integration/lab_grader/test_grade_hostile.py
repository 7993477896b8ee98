"""`rosrun lab_grader grade` on submissions that attack the grader (hostile_code.py) or hang it, next to an innocent
neighbour whose package holds a secret: graded in one run with a suite of the /move_service checks only, the batch
completes, each gets a verdict, and the sandbox holds: no process of a sandbox uid outlives the run, no network
beyond the box's loopback, nothing of the neighbour read, nothing written outside the workspace, logs capped."""
import json
import os
import re
import secrets
import socket
import subprocess
import threading
import time
from pathlib import Path

import pytest
import yaml

from lab_grader.grade import STUDENT_LIMITS
from lab_grader.sandbox import GRADER_SLOTS, STUDENT_UID_BASE
from lab_grader.sandbox_process import TRUNCATED_MARKER

from .conftest import LAB_ROOT
from .grading import check, grade, results
from .hostile_code import CHILDREN, REPORT_PREFIX, SLEEP_SECONDS
from .sample_submissions import make_submission

SANDBOX_UIDS = range(STUDENT_UID_BASE, STUDENT_UID_BASE + GRADER_SLOTS)
HOSTILE = ("forks_children", "reaches_network", "snoops", "prints_megabytes", "hangs_in_the_callback", "busy_waits")
NEIGHBOUR = "victim"        # sorts after "snoops": the two are graded at about the same time
SECRET_FILE = "secret_token.txt"
SUITE = LAB_ROOT / "catkin_ws" / "src" / "tools" / "lab_grader" / "suites" / "week4.yaml"
POLL_S = 0.2
READABLE = LAB_ROOT / "README.md"   # the lab checkout is readable by design: proof that the snooper's reads work


def move_service_suite(path: Path) -> Path:
    """The week4 suite cut down to the /move_service checks and the node that serves them."""
    suite = yaml.safe_load(SUITE.read_text())
    suite.update(suite="week4_move_only",
                 services=[service for service in suite["services"] if service["name"] == "/move_service"],
                 checks=[item for item in suite["checks"] if item["service"] == "/move_service"])
    path.write_text(yaml.safe_dump(suite))
    return path


def host_address():
    """A non-loopback IPv4 address of this host, or None."""
    try:
        listing = subprocess.run(["ip", "-4", "-o", "addr", "show", "scope", "global"], capture_output=True,
                                 text=True, timeout=10).stdout
    except OSError:
        return None
    addresses = re.findall(r"\binet (\d+\.\d+\.\d+\.\d+)/", listing)
    return addresses[0] if addresses else None


def sandbox_processes(uids=SANDBOX_UIDS):
    """{pid: command line} of every live process whose real uid is one of `uids` (default: any grader slot's)."""
    found = {}
    for entry in os.listdir("/proc"):
        if not entry.isdigit():
            continue
        try:
            status = Path("/proc", entry, "status").read_text()
            cmdline = Path("/proc", entry, "cmdline").read_bytes()
        except OSError:
            continue
        uid = int(re.search(r"^Uid:\s+(\d+)", status, re.M).group(1))
        state = re.search(r"^State:\s+(\S)", status, re.M).group(1)
        if uid in uids and state not in "ZX":
            found[int(entry)] = cmdline.replace(b"\0", b" ").decode(errors="replace").strip()
    return found


class SleeperWatch(threading.Thread):
    """Counts, while the grader runs, the most `sleep SLEEP_SECONDS` children of a sandbox uid seen at once."""

    def __init__(self):
        super().__init__(daemon=True)
        self.most = 0
        self.done = threading.Event()

    def run(self):
        while not self.done.wait(POLL_S):
            sleepers = [line for line in sandbox_processes().values() if line == "sleep {}".format(SLEEP_SECONDS)]
            self.most = max(self.most, len(sleepers))


def report(out, student):
    """The JSON line a hostile node printed in its log (hostile_code.REPORT_PREFIX)."""
    for line in (out / student / "node-1-move_server.py.log").read_text(errors="replace").splitlines():
        if line.startswith(REPORT_PREFIX):
            return json.loads(line[len(REPORT_PREFIX):])
    raise AssertionError("{} printed no report".format(student))


@pytest.fixture(scope="module")
def hostile(grader_env, ros_master, tmp_path_factory):
    folder = tmp_path_factory.mktemp("hostile_class")
    out = tmp_path_factory.mktemp("hostile_grades")
    token, marker = secrets.token_hex(16), "snooped-" + secrets.token_hex(8)
    neighbour = make_submission("reference", folder).rename(folder / NEIGHBOUR)
    secret = neighbour / "week4_services" / SECRET_FILE
    secret.write_text("the neighbour's secret: {}\n".format(token))
    listener = socket.create_server(("0.0.0.0", 0))     # reachable from this host, not from a box
    address = host_address()
    targets = [("internet", "1.1.1.1", 80), ("host_master", "127.0.0.1", ros_master.port)]
    if address:
        targets.append(("host_address", address, listener.getsockname()[1]))
    planted = [Path("/tmp", marker), folder / marker, secret.parent / marker, out / NEIGHBOUR / marker,
               LAB_ROOT / "catkin_ws" / "src" / marker, Path("/root", marker), Path.home() / marker]
    reads = [READABLE, secret, folder / "**" / "*"]
    fill = {"@NETWORK_TARGETS@": repr(targets), "@READ_PATHS@": repr([str(path) for path in reads]),
            "@LAB_ROOT@": repr(str(LAB_ROOT)),
            "@WRITE_PATHS@": repr([str(path) for path in planted]), "@MARKER@": marker}
    for name in HOSTILE:
        make_submission(name, folder, fill)
    suite = move_service_suite(tmp_path_factory.mktemp("suite") / "move_only.yaml")
    watch = SleeperWatch()
    watch.start()
    started = time.monotonic()
    try:
        output = grade(grader_env, folder, "--suite", suite, "--out", out, "--jobs", "2", "--rtf", "2")
    finally:
        watch.done.set()
        watch.join()
    wall_s = time.monotonic() - started
    # Only this run's uids: another grade run (a test module next to this one) may be busy in other slots.
    uids = {result["sandbox_uid"] for result in results(out).values()}
    left = sandbox_processes(uids)
    control = None
    if address:
        with socket.create_connection((address, listener.getsockname()[1]), timeout=5):
            control = "connected"
    listener.close()
    return dict(out=out, output=output, token=token, planted=planted, secret=secret, address=address,
                control=control, watch=watch, left=left, wall_s=wall_s, uids=uids)


@pytest.mark.slow
def test_the_batch_completes_with_a_verdict_per_check_for_every_student(hostile):
    graded = results(hostile["out"])
    assert sorted(graded) == sorted(HOSTILE + (NEIGHBOUR,))
    students = len(graded)
    assert "[{0}/{0}]".format(students) in hostile["output"]
    for student, result in graded.items():
        assert result["problems"] == [], (student, result["problems"])
        assert [check["id"] for check in result["checks"]] == ["move_true", "move_false"], student
    assert {check["verdict"] for check in graded[NEIGHBOUR]["checks"]} == {"pass"}
    print("hostile grade run: {:.0f} s, at most {} sleeping children seen at once".format(
        hostile["wall_s"], hostile["watch"].most))


@pytest.mark.slow
def test_children_that_leave_the_session_do_not_outlive_the_grading(hostile):
    assert report(hostile["out"], "forks_children") == {"children": CHILDREN}
    assert hostile["watch"].most > 0, "the children were never seen running"
    assert hostile["left"] == {}, "processes of a sandbox uid outlived the grader: {}".format(hostile["left"])
    assert sandbox_processes(hostile["uids"]) == {}
    result = results(hostile["out"])["forks_children"]
    assert {check["verdict"] for check in result["checks"]} == {"pass"}


@pytest.mark.slow
def test_a_node_reaches_nothing_but_its_boxs_loopback_and_its_server_still_passes(hostile):
    outcomes = report(hostile["out"], "reaches_network")
    assert outcomes["internet"] == "ENETUNREACH", outcomes
    assert outcomes["host_master"] == "ECONNREFUSED", "the box's loopback is its own: {}".format(outcomes)
    if hostile["address"]:
        assert hostile["control"] == "connected", "the host's own address must be reachable from the host"
        assert outcomes["host_address"] == "ENETUNREACH", outcomes
    result = results(hostile["out"])["reaches_network"]
    assert {check["verdict"] for check in result["checks"]} == {"pass"}, result["checks"]


@pytest.mark.slow
def test_a_snooper_reads_no_other_submission_and_writes_nothing_outside_its_workspace(hostile):
    out, token = hostile["out"], hostile["token"]
    found = report(out, "snoops")
    assert found["read"][str(READABLE)][:40] == READABLE.read_text()[:40], "the snooper's reads must work"
    assert str(hostile["secret"]) not in found["read"], found["read"]
    assert not any(token in text for text in found["read"].values())
    assert found["written"][str(LAB_ROOT / "catkin_ws" / "src" / hostile["planted"][0].name)] == "EROFS"
    for path in hostile["planted"]:
        assert not path.exists(), "the snooper wrote {}".format(path)
    for path in out.rglob("*"):     # the snooper's folder, and every other one
        if path.is_file():
            assert token.encode() not in path.read_bytes(), "the neighbour's secret is in {}".format(path)
    result = results(out)["snoops"]
    assert {check["verdict"] for check in result["checks"]} == {"pass"}, result["checks"]


@pytest.mark.slow
def test_megabytes_of_output_are_capped_in_the_logs_and_the_checks_still_run(hostile):
    folder = hostile["out"] / "prints_megabytes"
    log = folder / "node-1-move_server.py.log"
    cap = STUDENT_LIMITS.output_bytes
    assert log.stat().st_size <= cap
    assert TRUNCATED_MARKER.format(cap).strip() in log.read_text(errors="replace")
    for path in folder.iterdir():
        assert path.stat().st_size <= cap, path
    result = results(hostile["out"])["prints_megabytes"]
    assert {check["verdict"] for check in result["checks"]} <= {"pass", "fail", "error"}
    assert all(check["reason"] for check in result["checks"])


@pytest.mark.slow
@pytest.mark.parametrize("student", ["hangs_in_the_callback", "busy_waits"])
def test_a_callback_that_never_returns_errors_with_no_reply_and_the_batch_goes_on(hostile, student):
    result = results(hostile["out"])[student]
    for check_id in ("move_true", "move_false"):
        move = check(result, check_id)
        assert move["verdict"] == "error" and "no reply within" in move["reason"], move
