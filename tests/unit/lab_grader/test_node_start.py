"""How the grader starts a student's node and stops the previous one (lab_grader.grade), without a sandbox."""
import subprocess
import sys
import threading
import time
from pathlib import Path

from lab_grader.grade import Stopping, rosrun
from lab_grader.submissions import Submission


def test_the_node_file_found_is_run_from_the_workspace_after_sourcing_the_overlay(tmp_path):
    source = tmp_path / "alice"
    submission = Submission("alice", source, ("week4_alice",), source)
    command = rosrun(submission, source / "week4 alice" / "src" / "move_server.py")
    # the path inside the box's workspace (the submission's folder is its src/), quoted for bash
    assert command == ["bash", "-c", "source devel/setup.bash && exec 'src/week4 alice/src/move_server.py'"]


class SlowToStop:
    """A process whose stop() takes `seconds`, as a rospy node leaving the graph does."""

    def __init__(self, seconds):
        self.seconds, self.stopped = seconds, threading.Event()

    def stop(self):
        time.sleep(self.seconds)
        self.stopped.set()


def test_the_previous_node_is_stopped_meanwhile_and_joined_before_the_next_checks():
    node = SlowToStop(0.3)
    started = time.monotonic()
    stopping = Stopping(node)
    assert time.monotonic() - started < 0.2 and not node.stopped.is_set()   # the grader goes on at once
    stopping.join()
    assert node.stopped.is_set()
    Stopping(None).join()        # nothing to stop


def test_a_real_process_stopped_so_has_ended_after_join():
    process = subprocess.Popen([sys.executable, "-c", "import time; time.sleep(30)"])

    class Process:
        def stop(self):
            process.terminate()
            process.wait()

    Stopping(Process()).join()
    assert process.poll() is not None
    assert Path("/proc/{}".format(process.pid)).exists() is False
