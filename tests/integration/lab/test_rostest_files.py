"""Collector: every catkin_ws/src/**/test/*.test file runs through `rostest` as one pytest test.

rostest starts its own master on a free port for each file. A failure shows rostest's summary and the tail
of its output, and the full output is kept in the test's temporary folder.
"""
import os
import subprocess
from pathlib import Path

import pytest

REPO_ROOT = Path(__file__).resolve().parents[3]
ROSTEST_TIMEOUT_S = 600


REALTIME = {"beginner_tutorials/counter_action.test"}
"""Files whose assertions need their processes on time: the counter's first feedback goes out as the goal is
accepted, and a loaded machine may connect the client's feedback subscriber only after it."""


def rostest_files():
    return [pytest.param(path, marks=pytest.mark.realtime) if rostest_id(path) in REALTIME else path
            for path in sorted((REPO_ROOT / "catkin_ws" / "src").glob("**/test/*.test"))]


def rostest_id(path):
    package_dir = path.parent.parent
    return "{}/{}".format(package_dir.name, path.name)


@pytest.mark.parametrize("test_file", rostest_files(), ids=lambda path: rostest_id(path))
def test_rostest(test_file, tmp_path):
    env = dict(os.environ, ROS_HOME=str(tmp_path), ROS_LOG_DIR=str(tmp_path / "log"), PYTHONUNBUFFERED="1")
    result = subprocess.run(["rostest", str(test_file)], env=env, stdout=subprocess.PIPE,
                            stderr=subprocess.STDOUT, text=True, timeout=ROSTEST_TIMEOUT_S)
    (tmp_path / "rostest-output.txt").write_text(result.stdout)
    summary = result.stdout[result.stdout.rfind("[ROSTEST]"):] if "[ROSTEST]" in result.stdout else ""
    assert result.returncode == 0 and "RESULT: SUCCESS" in result.stdout, (
        "rostest {} failed (exit {}):\n{}\n--- last lines ---\n{}".format(
            rostest_id(test_file), result.returncode, summary, "\n".join(result.stdout.splitlines()[-60:])))
