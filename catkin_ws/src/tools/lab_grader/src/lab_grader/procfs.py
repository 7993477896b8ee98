"""What is running, read from /proc: the processes of a uid, of a network namespace, or below a process.

The sandbox's cleanup must prove that nothing of a submission survives, so it looks at the kernel's own view
(every process's uids, parent and namespace) instead of trusting its bookkeeping of what it started. Zombies are
left out: they no longer run, hold no resources but a pid, and are reaped by their parent.
"""
import os
import signal
import time
from typing import Callable, Dict, Iterator, List, NamedTuple, Optional

PROC = "/proc"
KILL_POLL_S = 0.02
ZOMBIE_STATES = ("Z", "X")  # exited, waiting to be reaped; dead


class ProcessInfo(NamedTuple):
    pid: int
    ppid: int
    uids: tuple  # (real, effective, saved, file-system)
    state: str  # one letter: R, S, D, T, Z, ...


def all_pids() -> Iterator[int]:
    for entry in os.listdir(PROC):
        if entry.isdigit():
            yield int(entry)


def process_info(pid: int) -> Optional[ProcessInfo]:
    """None when the process is gone (or went while being read)."""
    fields = {}
    try:
        with open("{}/{}/status".format(PROC, pid)) as status:
            for line in status:
                key, _, value = line.partition(":")
                if key in ("State", "PPid", "Uid"):
                    fields[key] = value.split()
    except (FileNotFoundError, ProcessLookupError):
        return None
    if len(fields) < 3:
        return None
    return ProcessInfo(pid, int(fields["PPid"][0]), tuple(int(uid) for uid in fields["Uid"]), fields["State"][0])


def is_alive(pid: int) -> bool:
    info = process_info(pid)
    return info is not None and info.state not in ZOMBIE_STATES


def live_processes() -> List[ProcessInfo]:
    """Every process but zombies."""
    infos = (process_info(pid) for pid in all_pids())
    return [info for info in infos if info is not None and info.state not in ZOMBIE_STATES]


def processes_of_uid(uid: int) -> List[int]:
    """Live processes with `uid` as any of their uids (a setuid helper keeps one of them)."""
    return [info.pid for info in live_processes() if uid in info.uids]


def net_namespace(pid: int) -> Optional[str]:
    """The process's network namespace as the kernel names it ("net:[4026532177]"), None if it is gone."""
    try:
        return os.readlink("{}/{}/ns/net".format(PROC, pid))
    except (FileNotFoundError, ProcessLookupError, PermissionError):
        return None


def processes_in_net_namespace(namespace: str) -> List[int]:
    return [info.pid for info in live_processes() if net_namespace(info.pid) == namespace]


def children(pid: int) -> List[int]:
    return [info.pid for info in live_processes() if info.ppid == pid]


def descendants(pid: int) -> List[int]:
    """Every live process below `pid` (children first), from one snapshot of /proc."""
    children: Dict[int, List[int]] = {}
    for info in live_processes():
        children.setdefault(info.ppid, []).append(info.pid)
    found, frontier = [], [pid]
    while frontier:
        below = [child for parent in frontier for child in children.get(parent, [])]
        found.extend(below)
        frontier = below
    return found


def signal_all(pids: List[int], signum: int) -> None:
    for pid in pids:
        try:
            os.kill(pid, signum)
        except (ProcessLookupError, PermissionError):
            pass  # gone already; PermissionError cannot happen as root, and a non-root caller checks the result


def kill_until_gone(find: Callable[[], List[int]], timeout_s: float) -> List[int]:
    """SIGKILL whatever `find()` returns, again and again (a fork bomb forks between two scans), until it returns
    nothing or `timeout_s` passed; returns what is still alive (empty on success)."""
    deadline = time.monotonic() + timeout_s
    while True:
        pids = find()
        if not pids or time.monotonic() > deadline:
            return pids
        signal_all(pids, signal.SIGKILL)
        time.sleep(KILL_POLL_S)
