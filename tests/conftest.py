"""Shared pytest fixtures. Run the suite through scripts/test, which sets up and sources scripts/env.sh."""
import json
import os
import resource
import signal
import sys
import time
from pathlib import Path

import pytest

TESTS_DIR = Path(__file__).resolve().parent
REPO_ROOT = TESTS_DIR.parent
sys.path.insert(0, str(TESTS_DIR))

from roslab import private_master  # noqa: E402  (needs the sys.path entry above)


def pytest_configure(config):
    if "ROS_PACKAGE_PATH" not in os.environ or "catkin_ws" not in os.environ.get("CMAKE_PREFIX_PATH", ""):
        raise pytest.UsageError("not a ROS terminal for this workspace: run scripts/test, or "
                                "`source scripts/env.sh` first")
    overlay = os.environ["CMAKE_PREFIX_PATH"].split(":")[0]
    if Path(overlay) != REPO_ROOT / "catkin_ws" / "devel":
        raise pytest.UsageError("the workspace {} overlays the lab in this terminal, so its packages would be tested "
                                "instead of the lab's: run scripts/test, or `LAB_STUDENT_WS=off source "
                                "scripts/env.sh` first".format(overlay))
    # Whatever a test starts that sources scripts/env.sh leaves the user's ~/catkin_ws alone; the tests of the
    # student's workspace set LAB_STUDENT_WS and HOME themselves.
    os.environ["LAB_STUDENT_WS"] = "off"
    # A run started in the background by a script (`(scripts/test &)`, nohup) ignores SIGINT, and every process a
    # test starts would inherit that: rosmaster, rosout and C++ nodes would then ignore the Ctrl-C that ends them
    # (roslab.processes), and each would hold its test up for the whole 20 s grace before SIGKILL.
    if signal.getsignal(signal.SIGINT) is signal.SIG_IGN:
        signal.signal(signal.SIGINT, signal.default_int_handler)


def recorded_wall_s(log=REPO_ROOT / "bench-output" / "module_cost.jsonl"):
    """{test file path: wall seconds} from the last whole scripts/test run (see _module_cost; a file with tests in
    both parts is counted once per part), or {} before one."""
    try:
        lines = Path(log).read_text().splitlines()
    except OSError:
        return {}
    walls = {}
    for line in lines:
        try:
            cost = json.loads(line)
            path = REPO_ROOT / cost["module"]
            walls[path] = walls.get(path, 0.0) + float(cost["wall_s"])
        except (ValueError, KeyError, TypeError):
            continue
    return walls


def pytest_collection_modifyitems(config, items):
    """Longest files first, so parallel workers (scripts/test: a whole file per pytest-xdist worker, in this order)
    do not end with one long integration module running alone: files with `slow` tests, then the other integration
    files, then the quick unit files to fill the gaps; within each of these, the longest in the last whole run
    first. The order of the tests inside a file is kept (a module's tests may build on each other's state)."""
    slow_files = {item.path for item in items if item.get_closest_marker("slow")}
    walls = recorded_wall_s()

    def weight(item):
        group = 0 if item.path in slow_files else 1 if "integration" in item.path.parts else 2
        return group, -walls.get(item.path, 0.0)
    items.sort(key=weight)


@pytest.fixture(scope="module")
def ros_master(tmp_path_factory):
    """A private master (rosmaster and rosout, see roslab.master) on a free port for this test module; every
    process started through it is ended when the module's tests are done. The test process's own ROS_MASTER_URI
    points at it too, so rospy.ServiceProxy calls (which need no init_node) reach it."""
    with private_master(tmp_path_factory.mktemp("ros")) as master:
        yield master


@pytest.fixture(scope="module")
def monkeypatch_module():
    with pytest.MonkeyPatch.context() as patch:
        yield patch


@pytest.fixture(scope="module")
def probe(ros_master):
    """A probe node (see roslab/probe_node.py) on the module's master."""
    return ros_master.probe()


def _cpu_seconds():
    """CPU seconds (user + system) of this process and of every child it has reaped (the master, nodes, and their
    own reaped children)."""
    own, children = resource.getrusage(resource.RUSAGE_SELF), resource.getrusage(resource.RUSAGE_CHILDREN)
    return own.ru_utime + own.ru_stime + children.ru_utime + children.ru_stime


@pytest.fixture(scope="module", autouse=True)
def _module_cost(request):
    """With LAB_TEST_COST_LOG set (scripts/test sets it), append one JSON line per test module to that file: how
    many of its tests this run selected, its wall seconds and CPU seconds, including the processes it started and
    ended (tests/bench/suite_cost.py sums them up). Set up before, and ended after, every other fixture of the
    module."""
    log = os.environ.get("LAB_TEST_COST_LOG")
    if not log:
        yield
        return
    wall, cpu = time.monotonic(), _cpu_seconds()
    yield
    path = Path(request.node.path)
    line = {"module": str(path.relative_to(REPO_ROOT)),
            "tests": sum(item.path == path for item in request.session.items),
            "wall_s": round(time.monotonic() - wall, 2), "cpu_s": round(_cpu_seconds() - cpu, 2)}
    with open(log, "a") as stream:
        stream.write(json.dumps(line) + "\n")
