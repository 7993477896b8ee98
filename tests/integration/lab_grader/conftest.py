"""Sandboxes for the lab_grader integration tests: a work root under /tmp (searchable by the sandbox uids, as the
sandbox requires) and boxes in two slots of their own, each closed (and its processes killed) even when a test
fails."""
import json
import os
import shutil
import tempfile
from pathlib import Path

import pytest

from lab_grader.sandbox import Limits, SubmissionSandbox

LAB_ROOT = Path(__file__).resolve().parents[3]
# Slots only these tests use, so they never wait for (or kill) a grader's own slots 0, 1, ...
SLOT_A = 900
SLOT_B = 901
TEST_LIMITS = Limits(cpu_s=2, processes=32, output_bytes=64 * 1024, wall_s=20.0)


@pytest.fixture
def work_root():
    path = Path(tempfile.mkdtemp(prefix="lab_grader-test-", dir="/tmp"))
    os.chmod(path, 0o711)
    yield path
    shutil.rmtree(path, ignore_errors=True)


@pytest.fixture
def box(work_root):
    with SubmissionSandbox(work_root, SLOT_A, LAB_ROOT, TEST_LIMITS) as box:
        yield box


@pytest.fixture
def other_box(work_root):
    with SubmissionSandbox(work_root, SLOT_B, LAB_ROOT, TEST_LIMITS) as box:
        yield box


@pytest.fixture(scope="module")
def grader_env(ros_master):
    """The ROS terminal's environment, for `rosrun lab_grader grade` (which starts its own masters inside the
    sandboxes), bound to the module's private master."""
    return dict(os.environ)


@pytest.fixture
def env():
    """The ROS terminal's environment, bound to the loopback master every box has at 11311."""
    environment = dict(os.environ, ROS_MASTER_URI="http://localhost:11311", ROS_HOSTNAME="localhost")
    environment.pop("ROS_IP", None)
    return environment


def last_json(log_path: Path):
    """The JSON report a test script printed as its last line."""
    return json.loads(Path(log_path).read_text().strip().splitlines()[-1])
