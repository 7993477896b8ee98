"""The grader's one command form, `sudo -E rosrun lab_grader grade ...`, as the README types it in a ROS terminal:
it runs (sudo drops PYTHONPATH and the venv's PATH; the grader restores them from its lab's scripts/env.sh), the
README uses no other form, and the grader run without root says what to type."""
import re
import subprocess
from pathlib import Path

import pytest

LAB_ROOT = Path(__file__).resolve().parents[3]
FORM = "sudo -E rosrun lab_grader grade"


def in_ros_terminal(command, tmp_path, user=None):
    """`command` in a bash that sourced scripts/env.sh (as `user` through runuser, else as this user)."""
    script = "export LAB_STUDENT_WS=off && source {} && {}".format(LAB_ROOT / "scripts" / "env.sh", command)
    prefix = ["runuser", "-u", user, "--"] if user else []
    return subprocess.run(prefix + ["bash", "-c", script], cwd=tmp_path, stdout=subprocess.PIPE,
                          stderr=subprocess.STDOUT, text=True, timeout=120)


def test_the_readme_uses_one_form_everywhere():
    readme = (LAB_ROOT / "README.md").read_text()
    commands = re.findall(r"(?:\S+ )*?rosrun lab_grader grade", readme)
    assert commands and all(command.endswith(FORM) for command in commands), commands


def test_sudo_e_rosrun_runs_the_grader(tmp_path):
    """The grader itself answers (an error about the missing submission), neither rosrun nor Python."""
    result = in_ros_terminal(FORM + " no_such_class/ --suite week4 --out grades/", tmp_path)
    assert "no_such_class does not exist" in result.stdout, result.stdout
    assert "Traceback" not in result.stdout and "not found" not in result.stdout, result.stdout
    assert result.returncode == 2


def test_sudo_e_rosrun_merges_shards(tmp_path):
    (tmp_path / "grades" / "1").mkdir(parents=True)
    result = in_ros_terminal(FORM + " --merge grades/1 --out grades/", tmp_path)
    assert "grade: merged 0 students into grades" in result.stdout, result.stdout
    assert result.returncode == 0


@pytest.mark.parametrize("arguments", ["submissions/ --out grades/", "'my class/' --suite week4 --out grades/"])
def test_without_root_it_says_what_to_type(tmp_path, arguments):
    tmp_path.chmod(0o777)
    for folder in ("submissions", "my class"):   # paths that exist: a missing one is told first
        (tmp_path / folder).mkdir()
    result = in_ros_terminal("rosrun lab_grader grade " + arguments, tmp_path, user="nobody")
    assert "grade: must run as root" in result.stdout, result.stdout
    assert result.stdout.splitlines()[-1].strip() == FORM + " " + arguments, result.stdout
    assert result.returncode == 2
