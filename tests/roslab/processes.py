"""A process of the ROS graph started by a test (rosmaster, rosrun, roslaunch, a CLI tool), always ended.

Each process runs in its own session (process group) so that ending it also ends everything roslaunch or
rosrun started under it. Output goes to a log file that failing tests can show.
"""
import os
import signal
import subprocess
import time
from pathlib import Path

CLOCK_TICKS_PER_S = os.sysconf("SC_CLK_TCK")
OFFSPRING_GRACE_S = 5.0


def _stat_fields(pid):
    """Fields of /proc/<pid>/stat after the command name (index 1 = parent pid, 19 = start time)."""
    return Path("/proc/{}/stat".format(pid)).read_text().rsplit(")", 1)[1].split()


def descendants(pid):
    """{(pid, start time)} of every living process descended from `pid`, from /proc. The start time tells
    a process apart from a later one that reuses its pid."""
    children_of = {}
    for entry in Path("/proc").iterdir():
        if entry.name.isdigit():
            try:
                fields = _stat_fields(entry.name)
            except OSError:
                continue
            children_of.setdefault(int(fields[1]), []).append((int(entry.name), fields[19]))
    found, frontier = set(), [pid]
    while frontier:
        children = children_of.get(frontier.pop(), [])
        found.update(children)
        frontier.extend(child for child, _ in children)
    return found


def alive(pid, started):
    """True while `pid` is still the process that started at `started` and has not exited (a zombie has)."""
    try:
        fields = _stat_fields(pid)
    except OSError:
        return False
    return fields[19] == started and fields[0] != "Z"


def kill_if_alive(pid, started):
    """SIGKILL `pid` if it is still the process that started at `started`."""
    if alive(pid, started):
        try:
            os.kill(pid, signal.SIGKILL)
        except OSError:
            pass


def _wait_for_exit(processes, deadline):
    """Wait until none of `processes` ({(pid, start time)}) is alive, or until time.monotonic() `deadline`."""
    while any(alive(*process) for process in processes) and time.monotonic() < deadline:
        time.sleep(0.05)


def cpu_seconds(pid):
    """User + system CPU seconds process `pid` has used so far (all its threads), from /proc."""
    fields = _stat_fields(pid)
    return (int(fields[11]) + int(fields[12])) / CLOCK_TICKS_PER_S


class RosProcess:
    """One command running against a given environment, with its output captured in `log_path`."""

    def __init__(self, command, env, log_path):
        self.command = list(command)
        self.log_path = log_path
        self._log = open(log_path, "wb")
        self.popen = subprocess.Popen(self.command, env=env, stdout=self._log, stderr=subprocess.STDOUT,
                                      stdin=subprocess.DEVNULL, start_new_session=True)
        self._interrupted = None   # (monotonic time, descendants seen before, whether it ran) at interrupt()

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

    def interrupt(self):
        """Ctrl-C (SIGINT to the process group), once; stop() begins with it. Interrupting several processes before
        stopping them lets them shut down side by side (see stop_together)."""
        if self._interrupted is None:
            offspring = set(descendants(self.popen.pid))
            running = self.running()
            if running:
                self.signal(signal.SIGINT)
            self._interrupted = (time.monotonic(), offspring, running)

    def stop(self, grace_s=20.0):
        """SIGINT (what Ctrl-C sends, so nodes run their shutdown hooks), then SIGKILL `grace_s` after it.

        A wrapper may exit before the children it forwarded Ctrl-C to (`rosbag record` leaves its recorder
        closing the bag), so descendants get up to OFFSPRING_GRACE_S more to finish on their own. roslaunch
        puts each node in a session of its own, so a node that outlives a killed roslaunch would escape the
        process group: every descendant seen before or during the shutdown is killed at the end."""
        self.interrupt()
        interrupted_at, offspring, was_running = self._interrupted
        if was_running:
            deadline = interrupted_at + grace_s
            try:
                self.popen.wait(timeout=max(0.0, deadline - time.monotonic()))
            except subprocess.TimeoutExpired:
                offspring.update(descendants(self.popen.pid))
            _wait_for_exit(offspring, min(deadline, time.monotonic() + OFFSPRING_GRACE_S))
        self.signal(signal.SIGKILL)
        self.popen.wait()
        for pid, started in offspring:
            kill_if_alive(pid, started)
        _wait_for_exit(offspring, time.monotonic() + OFFSPRING_GRACE_S)   # SIGKILL takes effect asynchronously
        self._log.close()
        return self.popen.returncode


def stop_together(processes):
    """Stop `processes` (RosProcess or TopicProbe) side by side: Ctrl-C to all, then wait for each. A rospy node
    takes about a second to shut down and a launch file as long as its slowest node; one after another, a module
    with a dozen of them spent up to 17 s in its teardown."""
    processes = list(processes)
    for process in processes:
        process.interrupt()
    for process in processes:
        process.stop()
