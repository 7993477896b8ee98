"""A process of the ROS graph started by a test (roscore, rosrun, roslaunch, a CLI tool), always ended.

Each process runs in its own session (process group) so that ending it also ends everything roslaunch or
rosrun started under it. Output goes to a log file that failing tests can show.
"""
import os
import signal
import subprocess
from pathlib import Path

CLOCK_TICKS_PER_S = os.sysconf("SC_CLK_TCK")


def cpu_seconds(pid):
    """User + system CPU seconds process `pid` has used so far (all its threads), from /proc."""
    fields = Path("/proc/{}/stat".format(pid)).read_text().rsplit(")", 1)[1].split()
    return (int(fields[11]) + int(fields[12])) / CLOCK_TICKS_PER_S


class RosProcess:
    """One command running against a given environment, with its output captured in `log_path`."""

    def __init__(self, command, env, log_path):
        self.command = list(command)
        self.log_path = log_path
        self._log = open(log_path, "wb")
        self.popen = subprocess.Popen(self.command, env=env, stdout=self._log, stderr=subprocess.STDOUT,
                                      stdin=subprocess.DEVNULL, start_new_session=True)

    @property
    def pid(self):
        return self.popen.pid

    def running(self):
        return self.popen.poll() is None

    def output(self):
        """Everything the process printed so far (stdout and stderr interleaved), also after stop()."""
        if not self._log.closed:
            self._log.flush()
        with open(self.log_path, "rb") as log:
            return log.read().decode("utf-8", "replace")

    def signal(self, signum):
        """Send `signum` to the whole process group (the command and its children)."""
        try:
            os.killpg(self.popen.pid, signum)
        except ProcessLookupError:
            pass

    def stop(self, grace_s=10.0):
        """SIGINT (what Ctrl-C sends, so nodes run their shutdown hooks), then SIGKILL after `grace_s`."""
        if self.running():
            self.signal(signal.SIGINT)
            try:
                self.popen.wait(timeout=grace_s)
            except subprocess.TimeoutExpired:
                pass
        self.signal(signal.SIGKILL)
        self.popen.wait()
        self._log.close()
        return self.popen.returncode
