"""RosProcess.stop ends what a test started the way Ctrl-C in a terminal would: children that a wrapper
forwarded the interrupt to may finish their work (rosbag record closing its bag) after the wrapper has exited,
and whatever is still alive after the grace period is killed."""
import sys

from roslab.processes import RosProcess, alive, descendants
from roslab.waiting import wait_until

WRAPPER = """
import subprocess, sys
child = subprocess.Popen([sys.executable, "-c", sys.argv[1]] + sys.argv[2:])
child.wait()   # Ctrl-C raises KeyboardInterrupt here: the wrapper exits without waiting, like rosbag record
"""
CLOSES_ON_CTRL_C = """
import signal, sys, time
def finish(*_):
    time.sleep(1.0)   # closing a bag takes a while
    open(sys.argv[1], "w").write("closed")
    sys.exit(0)
signal.signal(signal.SIGINT, finish)
open(sys.argv[2], "w").write("ready")
while True:
    time.sleep(1)
"""
IGNORES_CTRL_C = """
import signal, sys, time
signal.signal(signal.SIGINT, signal.SIG_IGN)
open(sys.argv[2], "w").write("ready")
while True:
    time.sleep(1)
"""


def start_wrapper(tmp_path, child_code):
    ready = tmp_path / "ready"
    process = RosProcess([sys.executable, "-c", WRAPPER, child_code, str(tmp_path / "closed"), str(ready)],
                         env=None, log_path=tmp_path / "log")
    wait_until(ready.exists, 30, "the child to start")
    return process


def test_a_child_finishes_its_work_after_the_wrapper_exits(tmp_path):
    process = start_wrapper(tmp_path, CLOSES_ON_CTRL_C)
    children = descendants(process.pid)
    process.stop()
    assert (tmp_path / "closed").read_text() == "closed"
    assert not any(alive(*child) for child in children)


def test_a_child_that_ignores_ctrl_c_is_killed(tmp_path):
    process = start_wrapper(tmp_path, IGNORES_CTRL_C)
    children = descendants(process.pid)
    assert children
    process.stop(grace_s=2.0)   # the grace a well-behaved process gets is not what this test is about
    assert not any(alive(*child) for child in children)
    assert not (tmp_path / "closed").exists()
