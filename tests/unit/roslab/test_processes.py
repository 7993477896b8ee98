"""RosProcess.stop ends what a test started the way Ctrl-C in a terminal would: children that a wrapper
forwarded the interrupt to may finish their work (rosbag record closing its bag) after the wrapper has exited,
and whatever is still alive after the grace period is killed. stop_together interrupts several at once."""
import sys

from roslab.processes import RosProcess, alive, descendants, stop_together
from roslab.waiting import wait_until

WRAPPER = """
import subprocess, sys
child = subprocess.Popen([sys.executable, "-c", sys.argv[1]] + sys.argv[2:])
child.wait()   # Ctrl-C raises KeyboardInterrupt here: the wrapper exits without waiting, like rosbag record
"""
CLOSES_ON_CTRL_C = """
import signal, sys, time
def finish(*_):
    interrupted = time.time()
    time.sleep(1.0)   # closing a bag takes a while
    open(sys.argv[1], "w").write("closed {} {}".format(interrupted, time.time()))
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
    assert (tmp_path / "closed").read_text().startswith("closed")
    assert not any(alive(*child) for child in children)


def test_a_child_finishes_its_work_when_the_wrapper_was_interrupted_and_exited_before_stop(tmp_path):
    process = start_wrapper(tmp_path, CLOSES_ON_CTRL_C)
    process.interrupt()
    process.popen.wait(timeout=30)
    process.stop()
    assert (tmp_path / "closed").read_text().startswith("closed")


def test_stop_together_interrupts_every_process_before_waiting_for_any(tmp_path):
    first, second = tmp_path / "first", tmp_path / "second"
    first.mkdir()
    second.mkdir()
    processes = [start_wrapper(first, CLOSES_ON_CTRL_C), start_wrapper(second, CLOSES_ON_CTRL_C)]
    stop_together(processes)
    (_, _, first_done), (_, second_interrupted, _) = (
        (folder / "closed").read_text().split() for folder in (first, second))
    assert float(second_interrupted) < float(first_done), "the second was interrupted only after the first ended"
    assert not any(process.running() for process in processes)


def test_a_child_that_ignores_ctrl_c_is_killed(tmp_path):
    process = start_wrapper(tmp_path, IGNORES_CTRL_C)
    children = descendants(process.pid)
    assert children
    process.stop(grace_s=2.0)   # the grace a well-behaved process gets is not what this test is about
    assert not any(alive(*child) for child in children)
    assert not (tmp_path / "closed").exists()
