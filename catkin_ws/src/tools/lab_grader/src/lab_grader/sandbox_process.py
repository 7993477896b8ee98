"""A process started by a sandbox, its capped log, and how its run ended.

A student's output goes through a pipe that the grader reads (`CappedLog`): the first `cap` bytes are stored, a
marker line says the rest was dropped, and the rest is read and discarded, so a program printing gigabytes neither
fills the disk nor blocks on a full pipe. Trusted processes write straight into their log file.

How a run ended is reported as a `RunResult`: the exit status when the program exited by itself, otherwise the
signal and a `StopReason`. Student commands run under bwrap, which exits with 128 + n when the program died of
signal n (as a shell does), so that status is read as a signal: a student program that calls exit(137) on purpose
is reported as killed. SIGXCPU means the CPU-time limit, SIGXFSZ the file-size limit; running out of address space
is not a signal (allocations fail and the program usually exits with an error of its own).
"""
import os
import signal
import subprocess
import threading
import time
from enum import Enum
from pathlib import Path
from typing import NamedTuple, Optional

from lab_grader import procfs

READ_CHUNK_BYTES = 64 * 1024
# After the process exits, how long its log reader may take to drain what is left in the pipe.
LOG_DRAIN_TIMEOUT_S = 5.0
DEFAULT_STOP_GRACE_S = 2.0
# How long kill() waits for a killed process tree to be gone.
KILL_TIMEOUT_S = 10.0
# Exit statuses above this mean "killed by signal (status - SHELL_SIGNAL_BASE)" for bwrap, as for a shell.
SHELL_SIGNAL_BASE = 128
TRUNCATED_MARKER = "\n[lab_grader: output truncated here; the log is capped at {} bytes]\n"


class StopReason(str, Enum):
    """Why a run did not end by exiting on its own."""
    TIMEOUT = "timeout"  # the wall-clock limit passed; the grader killed it
    STOPPED = "stopped"  # the grader stopped it (stop())
    CPU_LIMIT = "cpu_limit"  # SIGXCPU: it used up its CPU seconds
    FILE_SIZE_LIMIT = "file_size_limit"  # SIGXFSZ: it wrote a file larger than allowed
    KILLED = "killed"  # SIGKILL from elsewhere (the kernel's OOM killer, the CPU hard limit)
    SIGNALLED = "signalled"  # another signal: a crash (SIGSEGV, SIGABRT) or its own doing


SIGNAL_REASONS = {signal.SIGXCPU: StopReason.CPU_LIMIT, signal.SIGXFSZ: StopReason.FILE_SIZE_LIMIT,
                  signal.SIGKILL: StopReason.KILLED}


class RunResult(NamedTuple):
    returncode: Optional[int]  # exit status when it exited (also after a graceful stop), None when a signal ended it
    signal: Optional[int]  # the signal that ended it, or None
    stop_reason: Optional[StopReason]  # None when it exited on its own
    truncated: bool  # the log holds only the first output_bytes of its output
    duration_s: float  # wall-clock time from start to end
    log_path: Path

    @property
    def ok(self) -> bool:
        return self.stop_reason is None and self.returncode == 0


class CappedLog:
    """Copies everything readable from `read_fd` into `path`, storing at most `cap_bytes` (marker included)."""

    def __init__(self, read_fd: int, path: Path, cap_bytes: int):
        self._fd = read_fd
        self._path = Path(path)
        self._cap = cap_bytes
        self.stored_bytes = 0
        self.truncated = False
        self._file = open(self._path, "wb", buffering=0)  # exists on return; unbuffered: readable while it runs
        self._thread = threading.Thread(target=self._copy, name="log {}".format(self._path.name), daemon=True)
        self._thread.start()

    def _copy(self) -> None:
        marker = TRUNCATED_MARKER.format(self._cap).encode()
        room = max(self._cap - len(marker), 0)
        try:
            with self._file as log:
                while True:
                    chunk = os.read(self._fd, READ_CHUNK_BYTES)
                    if not chunk:
                        break
                    if self.truncated:
                        continue  # keep draining so the writer never blocks on a full pipe
                    if self.stored_bytes + len(chunk) <= room:
                        log.write(chunk)
                        self.stored_bytes += len(chunk)
                        continue
                    head = chunk[:room - self.stored_bytes]
                    log.write(head + (marker if len(marker) <= self._cap else b""))
                    self.stored_bytes += len(head)
                    self.truncated = True
        finally:
            os.close(self._fd)

    def join(self, timeout_s: float) -> None:
        self._thread.join(timeout_s)


class SandboxProcess:
    """One process a sandbox started: a trusted one (its own session, stopped through its process group) or a
    student's (bwrap's pid namespace, stopped by killing bwrap, which takes every process inside with it)."""

    def __init__(self, popen: subprocess.Popen, log_path: Path, sandboxed: bool, log: Optional[CappedLog] = None):
        self._popen = popen
        self._log = log
        self._sandboxed = sandboxed
        self._started = time.monotonic()
        self._ended: Optional[float] = None
        self._stop_reason: Optional[StopReason] = None
        self.log_path = Path(log_path)
        self.argv = popen.args

    @property
    def sandboxed(self) -> bool:
        """True for a student's process (setpriv, prlimit and bwrap around the command)."""
        return self._sandboxed

    @property
    def pid(self) -> int:
        """The pid of the process the grader started (for a student's command: the outer bwrap)."""
        return self._popen.pid

    def running(self) -> bool:
        return self._popen.poll() is None

    def send_line(self, line: str) -> bool:
        """Write one line to the process's command pipe (a trusted process started with `commands`); False when
        it has closed its end (it exited)."""
        try:
            self._popen.stdin.write(line + "\n")
            self._popen.stdin.flush()
        except (BrokenPipeError, ValueError):   # ValueError: the pipe was closed on our side
            return False
        return True

    def close_input(self) -> None:
        """End the command pipe: the process reads end of file."""
        if self._popen.stdin is not None:
            try:
                self._popen.stdin.close()
            except BrokenPipeError:
                pass

    def wait(self, timeout_s: Optional[float] = None) -> RunResult:
        """Wait for the end; past `timeout_s` (None: no limit), kill it and report a TIMEOUT."""
        try:
            self._popen.wait(timeout_s)
        except subprocess.TimeoutExpired:
            self._stop_reason = StopReason.TIMEOUT
            self.kill()
        return self._result()

    def stop(self, grace_s: float = DEFAULT_STOP_GRACE_S) -> RunResult:
        """SIGINT (what Ctrl+C sends, which ROS nodes handle), then SIGKILL after `grace_s`."""
        if self.running():
            self._stop_reason = StopReason.STOPPED
            self._signal_program(signal.SIGINT)
            try:
                self._popen.wait(grace_s)
            except subprocess.TimeoutExpired:
                self.kill()
        return self._result()

    def kill(self) -> None:
        """SIGKILL the process and everything it started, and reap it."""
        if self._sandboxed:
            # bwrap's outer process first: --die-with-parent then kills the pid namespace's init, and with it every
            # process inside; the rest is belt and braces for processes between two states.
            tree = [self._popen.pid] + procfs.descendants(self._popen.pid)
            procfs.signal_all(tree, signal.SIGKILL)
            self._popen.wait()
            # SIGKILL takes effect asynchronously: return only once the whole tree is gone.
            procfs.kill_until_gone(lambda: [pid for pid in tree if procfs.is_alive(pid)], KILL_TIMEOUT_S)
        elif self._popen.poll() is None:
            try:
                os.killpg(self._popen.pid, signal.SIGKILL)
            except ProcessLookupError:
                pass
        self._popen.wait()

    def _signal_program(self, signum: int) -> None:
        if not self._sandboxed:
            try:
                os.killpg(self._popen.pid, signum)
            except ProcessLookupError:
                pass
            return
        # Inside bwrap: outer bwrap -> init (pid 1 inside) -> the student's program and its children. Only the
        # program's tree gets the signal; bwrap's own processes only pass exit statuses on.
        inits = procfs.children(self._popen.pid)
        procfs.signal_all([pid for init in inits for pid in procfs.descendants(init)], signum)

    def _result(self) -> RunResult:
        if self._ended is None:
            self._ended = time.monotonic()
        self.close_input()
        truncated = False
        if self._log is not None:
            self._log.join(LOG_DRAIN_TIMEOUT_S)
            truncated = self._log.truncated
        status = self._popen.returncode
        signum = None
        if status < 0:
            signum = -status
        elif self._sandboxed and SHELL_SIGNAL_BASE < status < SHELL_SIGNAL_BASE + signal.NSIG:
            signum = status - SHELL_SIGNAL_BASE
        reason = self._stop_reason
        if reason is None and signum is not None:
            reason = SIGNAL_REASONS.get(signum, StopReason.SIGNALLED)
        returncode = status if signum is None else None
        return RunResult(returncode, signum, reason, truncated, self._ended - self._started, self.log_path)
