"""A private network namespace per submission, held open by a small process.

Each submission gets a network namespace of its own with only loopback up: its roscore can listen on
127.0.0.1:11311 while another submission's does the same in its own namespace, and nothing in it can reach any
other host (there is no interface but `lo`, so a connect() elsewhere fails at once with ENETUNREACH).

The namespace lives as long as a holder process: `unshare --net` makes it, `ip link set lo up` brings loopback up,
then the holder sleeps. Every process of the submission joins it with `nsenter --net=/proc/<holder>/ns/net`.
The holder gets SIGKILL when the thread that started it ends (`setpriv --pdeathsig`), so a crashed grader does not
leave it behind: start and close a sandbox in the same thread.

The holder is the grader's child and is not reaped before `stop()`, so its pid cannot be reused by another process
while the sandbox may still nsenter it; `path` refuses to name a holder that has exited.
"""
import os
import select
import shutil
import subprocess
from typing import List

from lab_grader.errors import SandboxError

HOLDER_READY_TIMEOUT_S = 5.0
HOLDER_READY_LINE = b"ready\n"
HOLDER_SCRIPT = "ip link set lo up && echo ready && exec sleep infinity"
TOOLS = ("unshare", "nsenter", "setpriv", "ip")


def find_tool(name: str) -> str:
    """Absolute path of a command-line tool, or SandboxError naming the Debian package that has it."""
    path = shutil.which(name, path="/usr/sbin:/usr/bin:/sbin:/bin")
    if path is None:
        packages = {"bwrap": "bubblewrap", "ip": "iproute2", "pkill": "procps"}
        raise SandboxError("{} is missing: apt-get install {}".format(name, packages.get(name, "util-linux")))
    return path


class NetnsHolder:
    """Owns one network namespace (loopback only) through a sleeping holder process."""

    def __init__(self):
        self._tools = {name: find_tool(name) for name in TOOLS}
        self._process = None

    def start(self) -> None:
        argv = [self._tools["unshare"], "--net", "--", self._tools["setpriv"], "--pdeathsig", "KILL", "--",
                "/bin/sh", "-c", HOLDER_SCRIPT]
        self._process = subprocess.Popen(argv, stdin=subprocess.DEVNULL, stdout=subprocess.PIPE,
                                         stderr=subprocess.PIPE, cwd="/", env={"PATH": "/usr/sbin:/usr/bin"})
        ready, _, _ = select.select([self._process.stdout], [], [], HOLDER_READY_TIMEOUT_S)
        line = os.read(self._process.stdout.fileno(), len(HOLDER_READY_LINE)) if ready else b""
        self._process.stdout.close()
        if line != HOLDER_READY_LINE:
            self.stop()
            error = self._process.stderr.read().decode(errors="replace").strip()
            raise SandboxError("could not create a network namespace: {}".format(error or "no answer in time"))
        self._process.stderr.close()
        if os.readlink(self.path) == os.readlink("/proc/self/ns/net"):
            self.stop()
            raise SandboxError("unshare --net did not create a new network namespace")

    @property
    def pid(self) -> int:
        return self._process.pid

    @property
    def path(self) -> str:
        """/proc/<holder>/ns/net, for nsenter; SandboxError if the holder has died."""
        if self._process is None or self._process.poll() is not None:
            raise SandboxError("the network namespace holder is not running")
        return "/proc/{}/ns/net".format(self._process.pid)

    @property
    def namespace(self) -> str:
        """The kernel's name for the namespace ("net:[4026532177]"), to find every process inside it."""
        return os.readlink(self.path)

    def enter_argv(self) -> List[str]:
        """The argv prefix that runs a command inside the namespace."""
        return [self._tools["nsenter"], "--net={}".format(self.path), "--"]

    def running(self) -> bool:
        return self._process is not None and self._process.poll() is None

    def stop(self) -> None:
        """Kill and reap the holder (the namespace goes once no process is left in it)."""
        if self._process is None:
            return
        if self._process.poll() is None:
            self._process.kill()
        self._process.wait()
