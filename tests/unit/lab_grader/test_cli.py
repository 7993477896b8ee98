"""`rosrun lab_grader grade` with a path that does not exist: one line naming it and exit 2, as its usage says, in
both modes (no traceback, and no sandbox is set up first)."""
import subprocess

import pytest


@pytest.mark.parametrize("mode", [(), ("--merge",)])
def test_a_path_that_does_not_exist_exits_2_with_one_line(tmp_path, mode):
    missing = tmp_path / "no-such-class"
    run = subprocess.run(["rosrun", "lab_grader", "grade", *mode, str(missing), "--out", str(tmp_path / "out")],
                         capture_output=True, text=True, timeout=60)
    assert (run.returncode, run.stdout, run.stderr) == (2, "", "grade: {} does not exist\n".format(missing))
    assert not (tmp_path / "out").exists()
