"""Fixtures shared by integration test modules (tests/conftest.py has the master and the probe)."""
from pathlib import Path

import pytest

from roslab.terminal import Terminal, student_env

REPO_ROOT = Path(__file__).resolve().parents[2]


@pytest.fixture(scope="module")
def home(tmp_path_factory):
    """A temporary HOME whose .bashrc sources scripts/env.sh, as a student's does."""
    home = tmp_path_factory.mktemp("home")
    (home / ".bashrc").write_text("source {}\n".format(REPO_ROOT / "scripts" / "env.sh"))
    return home


@pytest.fixture(scope="module")
def terminal(ros_master, home, tmp_path_factory):
    """An interactive bash in a pseudo-terminal in `home`, on the module's master (closed after the module)."""
    env = student_env(home, ROS_MASTER_URI=ros_master.uri, ROS_HOSTNAME="localhost", LAB_STUDENT_WS="off",
                      ROS_LOG_DIR=str(ros_master.workdir / "log"))
    terminal = Terminal(env, home, tmp_path_factory.mktemp("terminal") / "terminal.log")
    yield terminal
    terminal.close()
