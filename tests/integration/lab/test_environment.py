"""scripts/env.sh makes a ROS terminal for this workspace whatever python3 came first on PATH (also when it is
sourced again after something put another python3 first), binds ROS to localhost unless the user chose
otherwise, and scripts/setup re-runs as a no-op. HOME is a temporary folder (env.sh creates the student's
workspace there)."""
import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

REPO_ROOT = Path(__file__).resolve().parents[3]


@pytest.fixture
def foreign_python_first(tmp_path):
    """A PATH whose first python3 is not Debian's (like pyenv's shim on these machines): it cannot import rospy."""
    shim_dir = tmp_path / "shims"
    shim_dir.mkdir()
    shim = shim_dir / "python3"
    shim.write_text("#!/bin/sh\necho 'foreign python3: no rospy here' >&2\nexit 1\n")
    shim.chmod(0o755)
    return "{}:/usr/local/bin:/usr/bin:/bin".format(shim_dir)


@pytest.fixture(autouse=True)
def home(tmp_path, monkeypatch):
    """A temporary HOME for in_fresh_terminal."""
    monkeypatch.setenv("HOME", str(tmp_path / "home"))
    return tmp_path / "home"


def in_fresh_terminal(script, path, **env):
    """Run `script` in `bash` with a minimal environment (HOME from the `home` fixture, no student workspace:
    test_student_workspace.py tests that) after `source scripts/env.sh`."""
    clean = {"HOME": os.environ["HOME"], "PATH": path, "LAB_STUDENT_WS": "off", **env}
    result = subprocess.run(["bash", "-c", "source scripts/env.sh && " + script], cwd=REPO_ROOT, env=clean,
                            stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, timeout=300)
    return result.returncode, result.stdout


def test_venv_python_wins_and_imports_ros(foreign_python_first):
    code, output = in_fresh_terminal(
        "command -v python3 && python3 -c 'import rospy, tuos_msgs.srv, Box2D; print(\"imports ok\")'",
        foreign_python_first)
    assert code == 0, output
    assert output.splitlines()[0] == str(REPO_ROOT / ".venv" / "bin" / "python3")
    assert "imports ok" in output


def test_sourcing_again_puts_the_venv_first_again(foreign_python_first):
    """What `src` does after `source ~/.bashrc` let pyenv put its python3 first (the venv stays on PATH)."""
    shims = foreign_python_first.split(":")[0]
    code, output = in_fresh_terminal(
        'export PATH="{}:$PATH" && source scripts/env.sh && command -v python3 && echo "$PATH"'.format(shims),
        foreign_python_first)
    assert code == 0, output
    venv_bin = str(REPO_ROOT / ".venv" / "bin")
    assert output.splitlines()[0] == venv_bin + "/python3"
    assert output.splitlines()[1].split(":") == [venv_bin, shims, shims, "/usr/local/bin", "/usr/bin", "/bin"]


def test_ros_tools_are_on_path(foreign_python_first):
    code, output = in_fresh_terminal(
        "for tool in rosrun roslaunch rosservice rossrv rostest catkin_make roscore; do command -v $tool; done"
        " && rospack find tuos_msgs", foreign_python_first)
    assert code == 0, output
    assert output.splitlines()[-1] == str(REPO_ROOT / "catkin_ws/src/interfaces/tuos_msgs")


def test_binds_to_localhost_by_default(foreign_python_first):
    code, output = in_fresh_terminal('echo "$ROS_HOSTNAME $ROS_MASTER_URI ${ROS_IP:-unset}"', foreign_python_first)
    assert code == 0, output
    assert output.strip() == "localhost http://localhost:11311 unset"


def test_user_network_settings_are_kept(foreign_python_first):
    code, output = in_fresh_terminal('echo "${ROS_HOSTNAME:-unset} $ROS_MASTER_URI $ROS_IP"', foreign_python_first,
                                     ROS_MASTER_URI="http://robot.local:11311", ROS_IP="10.0.0.5")
    assert code == 0, output
    assert output.strip() == "unset http://robot.local:11311 10.0.0.5"


def test_src_alias_resources_the_environment(foreign_python_first):
    code, output = in_fresh_terminal("shopt -s expand_aliases; alias src", foreign_python_first)
    assert code == 0, output
    assert "scripts/env.sh" in output


@pytest.mark.slow
def test_catkin_make_works_despite_foreign_python(foreign_python_first, tmp_path):
    """catkin_make into a fresh build folder, so CMake detects Python afresh instead of reading the workspace's
    cache (and the workspace's own build is left as it was); tuos_msgs and its dependencies only, for speed."""
    code, output = in_fresh_terminal(
        "cd catkin_ws && catkin_make --build {0}/build -DCATKIN_DEVEL_PREFIX={0}/devel "
        "--only-pkg-with-deps tuos_msgs".format(tmp_path), foreign_python_first)
    assert code == 0, output[-3000:]
    assert "PYTHON_EXECUTABLE: {}".format(REPO_ROOT / ".venv/bin/python3") in output
    assert list((tmp_path / "devel").glob("lib/python3*/dist-packages/tuos_msgs/srv/_SetBool.py")), output[-3000:]


def run_setup():
    result = subprocess.run([str(REPO_ROOT / "scripts" / "setup")], stdout=subprocess.PIPE,
                            stderr=subprocess.STDOUT, text=True, timeout=1800)
    assert result.returncode == 0, result.stdout
    return result.stdout


def test_second_setup_is_a_no_op_that_says_so():
    """Also after Python wrote byte-code caches under catkin_ws/src, as every import of a lab module does: they
    used to count as changed sources, so each scripts/test rebuilt the workspace while its tests were running."""
    run_setup()
    cache = REPO_ROOT / "catkin_ws/src/lib/tb3_client/src/tb3_client/__pycache__"
    shutil.rmtree(cache, ignore_errors=True)
    env = {name: value for name, value in os.environ.items() if name != "PYTHONDONTWRITEBYTECODE"}
    subprocess.run([sys.executable, "-c", "import tb3_client.commands"], env=env, check=True)
    assert list(cache.glob("commands.*.pyc"))
    second = run_setup()
    assert second.count("already done") == 3, second
    assert "catkin_make (log" not in second
