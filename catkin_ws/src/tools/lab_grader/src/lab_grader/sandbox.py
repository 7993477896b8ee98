"""One submission's sandbox: where its untrusted build and nodes run, next to the trusted roscore, simulator and
checks that grade it.

    with SubmissionSandbox(work_root, slot, lab_root, limits) as box:
        box.copy_into_workspace(submission.source_dir, "src")
        box.start_trusted(["roscore"], ros_env, logs / "roscore.log")
        result = box.run_student(["catkin_make"], ros_env, logs / "build.log", timeout_s=300)

Isolation, layer by layer:
- Network: the box's own network namespace with only loopback (`netns.NetnsHolder`). Every process of the box,
  trusted or not, runs in it, so its roscore can use port 11311 whatever the other boxes do, and nothing reaches
  another host.
- Identity: student processes run as uid/gid `STUDENT_UID_BASE + slot`, with no supplementary groups, no
  capabilities and no_new_privs (`setpriv`): they cannot signal, ptrace or write the grader's processes and files
  (root's), nor another slot's. Each slot is locked machine-wide (`SLOT_LOCK_DIR`), so two sandboxes never share
  a uid.
- File system and processes: bubblewrap (`bwrap.bwrap_args`): the host read-only, the box's workspace read-write,
  a private /tmp and /dev/shm, the work root (every other submission) hidden, its own pid namespace (the grader's
  processes are not even visible).
- Priority: student processes run at niceness STUDENT_NICENESS, below the trusted simulator and checks.
- Resources (`Limits`, set with `prlimit` on the student's process tree): CPU seconds, address space and file size
  per process; processes and threads of the slot's uid all together (so a node left running counts against the
  next command of the same box); open files; a wall-clock timeout per run; a capped log; and the whole workspace,
  a tmpfs of `workspace_bytes` (`workspace_mount`), so many files cannot add up past it either.
- Root and the workspace: the workspace belongs to the student's uid, so the grader writes into it only through
  `copy_into_workspace` (refused while a student process runs) and never puts a log there.
- Cleanup (`close()`, also on errors): every started process is killed, then every process left in the box's
  network namespace, then every process of the slot's uid (checked on /proc until none is left), then the
  namespace holder; the workspace is unmounted (its content goes with it) and the box's folder deleted.

Trusted commands are the grader's own (roscore, the simulator, the checks): they run as root, in the box's network
namespace, in their own session, with their output written straight to their log.

Limits of this layer, on purpose: CPU time and memory are per process, not per box (a cgroup would cap the total);
the workspace takes memory, not disk, up to `workspace_bytes` per box. A trusted process that daemonizes is found
and killed at close() through the network namespace, but if the grader itself is killed, only the direct trusted
processes (PR_SET_PDEATHSIG), the holder and the student processes (--die-with-parent) die with it; the next
sandbox of the slot kills what is left of its uid and unmounts its workspaces. The tools come from Debian:
bubblewrap, util-linux (unshare, nsenter, setpriv, prlimit), mount and iproute2.

A sandbox is used from one thread: the namespace holder dies with the thread that entered the sandbox.
"""
import fcntl
import os
import pwd
import shutil
import stat
import subprocess
import tempfile
from pathlib import Path
from typing import Dict, List, NamedTuple, Optional, Sequence

from lab_grader import procfs
from lab_grader.bwrap import STUDENT_NAME, bwrap_args, passwd_with_student
from lab_grader.errors import SandboxError
from lab_grader.netns import NetnsHolder, find_tool
from lab_grader.sandbox_process import CappedLog, RunResult, SandboxProcess
from lab_grader.workspace_mount import mount_workspace, stale_mounts, unmount

__all__ = ["Limits", "SandboxError", "SubmissionSandbox", "STUDENT_UID_BASE"]

MIB = 1024 * 1024
GIB = 1024 * MIB
STUDENT_UID_BASE = 61000
MAX_SLOTS = 1000
# After SIGXCPU at the CPU limit, a process that handles it gets SIGKILL this much later.
CPU_HARD_GRACE_S = 1
# How long cleanup keeps killing before it declares a process unkillable (a process in uninterruptible sleep).
KILL_TIMEOUT_S = 10.0
WORKSPACE_MODE = 0o700
# Student processes run at this niceness: a busy-waiting callback must not starve the box's simulator and checks
# (which would turn one student's mistake into wrong motion measurements); CPU time limits still apply.
STUDENT_NICENESS = 10
# Slot locks are machine-wide (not per work root): two graders must never share a uid.
SLOT_LOCK_DIR = Path("/run/lab_grader")
SLOT_LOCK_NAME = "slot-{}.lock"
BOX_PREFIX = "slot{}-"
WORKSPACE_NAME = "workspace"


class Limits(NamedTuple):
    """Resource limits of a box's student processes. Defaults suit building and running a course package."""
    cpu_s: int = 60  # CPU seconds per process (RLIMIT_CPU): SIGXCPU, then SIGKILL CPU_HARD_GRACE_S later
    memory_bytes: int = 4 * GIB  # address space per process (RLIMIT_AS); rospy's threads reserve much
    processes: int = 256  # processes and threads of the slot's uid together (RLIMIT_NPROC)
    output_bytes: int = 1 * MIB  # stored per log; the rest is dropped and the run marked truncated
    file_bytes: int = 256 * MIB  # largest file a process may write (RLIMIT_FSIZE): SIGXFSZ beyond
    open_files: int = 1024  # per process (RLIMIT_NOFILE)
    tmp_bytes: int = 256 * MIB  # size of the private /tmp, and of /dev/shm (each memory-backed)
    workspace_bytes: int = 1 * GIB  # the whole workspace: sources, build, devel, logs (a memory-backed tmpfs)
    wall_s: float = 120.0  # wall-clock timeout of run_student/run_trusted when none is given


GRADER_SLOTS = 100
"""Slots 0..GRADER_SLOTS-1 are handed to grader workers by reserve_slot (higher ones are free for tests)."""
RESERVATION_NAME = "worker-{}.lock"
TRUSTED_ROS_HOME = "trusted_ros"


class SlotReservation:
    """A slot held for one grader worker as long as it lives, machine-wide: a flock on SLOT_LOCK_DIR/worker-<slot>.lock
    (released by `release()`, or by the kernel when the grader exits however it ends). Two grade runs at once (two
    instructors, a test next to a real run) so never pick the same slot; each sandbox still locks its slot itself."""

    def __init__(self, slot: int, fd: int):
        self.slot, self._fd = slot, fd

    def release(self) -> None:
        if self._fd is not None:
            os.close(self._fd)
            self._fd = None


def reserve_slot() -> SlotReservation:
    """The lowest slot no other grader worker holds (SandboxError when all GRADER_SLOTS are taken)."""
    SLOT_LOCK_DIR.mkdir(mode=0o700, parents=True, exist_ok=True)
    for slot in range(GRADER_SLOTS):
        fd = os.open(SLOT_LOCK_DIR / RESERVATION_NAME.format(slot), os.O_RDWR | os.O_CREAT, 0o600)
        try:
            fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except BlockingIOError:
            os.close(fd)
            continue
        return SlotReservation(slot, fd)
    raise SandboxError("all {} grader slots are taken by other graders".format(GRADER_SLOTS))


class SubmissionSandbox:
    """The sandbox of one submission in one parallel slot; a context manager (see the module docstring)."""

    def __init__(self, work_root: Path, slot: int, lab_root: Path, limits: Limits = Limits()):
        self.work_root = Path(work_root).resolve()
        self.lab_root = Path(lab_root).resolve()
        self.slot = slot
        self.limits = limits
        self.uid = self.gid = STUDENT_UID_BASE + slot
        self.workspace: Optional[Path] = None
        self._workspace_mounted = False
        self._tools = {name: find_tool(name) for name in ("nsenter", "setpriv", "prlimit", "nice", "bwrap")}
        self._netns: Optional[NetnsHolder] = None
        self._namespace: Optional[str] = None  # kept: cleanup needs it even if the holder died
        self._lock_fd: Optional[int] = None
        self._box_dir: Optional[Path] = None
        self._processes: List[SandboxProcess] = []
        self._check_settings()

    def _check_settings(self) -> None:
        if os.geteuid() != 0:
            raise SandboxError("the sandbox must be set up by root (it switches to the slot's uid)")
        if not 0 <= self.slot < MAX_SLOTS:
            raise SandboxError("slot {} is outside 0..{}".format(self.slot, MAX_SLOTS - 1))
        try:
            user = pwd.getpwuid(self.uid).pw_name
        except KeyError:
            user = None
        if user is not None:
            raise SandboxError("uid {} (slot {}) belongs to the user {}: its processes would be killed".format(
                self.uid, self.slot, user))
        if not self.lab_root.is_dir():
            raise SandboxError("the lab root {} is not a folder".format(self.lab_root))
        if self.lab_root == self.work_root or self.work_root in self.lab_root.parents:
            raise SandboxError("the lab root {} must not be inside the work root {}, which the sandbox hides".format(
                self.lab_root, self.work_root))
        if self.work_root.parent == self.work_root:
            raise SandboxError("the work root must not be /")

    def __enter__(self) -> "SubmissionSandbox":
        try:
            self._open()
        except BaseException:
            self.close()
            raise
        return self

    def __exit__(self, *exc_info) -> None:
        self.close()

    def _open(self) -> None:
        self.work_root.mkdir(mode=0o711, parents=True, exist_ok=True)
        check_searchable(self.work_root)
        SLOT_LOCK_DIR.mkdir(mode=0o700, parents=True, exist_ok=True)
        self._lock_fd = os.open(SLOT_LOCK_DIR / SLOT_LOCK_NAME.format(self.slot), os.O_RDWR | os.O_CREAT, 0o600)
        try:
            fcntl.flock(self._lock_fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except BlockingIOError:
            os.close(self._lock_fd)
            self._lock_fd = None
            raise SandboxError("slot {} is in use by another sandbox".format(self.slot)) from None
        self._kill_slot_uid()  # leftovers of a grader that crashed while holding this slot
        for stale in stale_mounts(self.work_root, BOX_PREFIX.format(self.slot), WORKSPACE_NAME):
            unmount(stale)
        self._netns = NetnsHolder()
        self._netns.start()
        self._namespace = self._netns.namespace
        self._box_dir = Path(tempfile.mkdtemp(prefix=BOX_PREFIX.format(self.slot), dir=self.work_root))
        os.chmod(self._box_dir, 0o711)  # the student's uid must pass through to reach its workspace
        (self._box_dir / TRUSTED_ROS_HOME).mkdir(mode=0o700)   # trusted_env's ROS logs: root only
        self.workspace = self._box_dir / WORKSPACE_NAME
        self.workspace.mkdir(mode=WORKSPACE_MODE)
        mount_workspace(self.workspace, self.limits.workspace_bytes, self.uid, self.gid, WORKSPACE_MODE)
        self._workspace_mounted = True

    @property
    def netns_holder_pid(self) -> int:
        return self._netns.pid

    @property
    def net_namespace(self) -> str:
        """The kernel's name of the box's network namespace ("net:[...]")."""
        return self._namespace

    def student_env(self, env: Dict[str, str]) -> Dict[str, str]:
        """`env` with what must point into the workspace for the student's uid: HOME, ROS_HOME, ROS_LOG_DIR, and
        the user's name; TMPDIR is the private /tmp."""
        ros_home = self.workspace / ".ros"
        return dict(env, HOME=str(self.workspace), ROS_HOME=str(ros_home), ROS_LOG_DIR=str(ros_home / "log"),
                    USER=STUDENT_NAME, LOGNAME=STUDENT_NAME, TMPDIR="/tmp")

    def copy_into_workspace(self, source: Path, relative_dest: str) -> Path:
        """Copy a folder into the workspace, owned by the slot's uid so the student's build can write there;
        symlinks are copied as symlinks, never followed. The workspace belongs to the student, so this root-run
        copy is refused while a student process runs (it could swap a folder for a symlink meanwhile), and when the
        destination already exists or its folder resolves outside the workspace (a symlink an earlier run made)."""
        # A started student command counts before it has switched to the slot's uid (setpriv runs first as root).
        if self.student_processes() or any(process.sandboxed and process.running() for process in self._processes):
            raise SandboxError("copy into the workspace only while no student process runs")
        dest = self.workspace / relative_dest
        if os.path.lexists(dest) or not is_inside(Path(os.path.realpath(dest.parent)), self.workspace):
            raise SandboxError("{} already exists or leads outside the workspace".format(relative_dest))
        shutil.copytree(source, dest, symlinks=True)
        for folder, subfolders, files in os.walk(dest):
            for name in [folder] + [os.path.join(folder, entry) for entry in subfolders + files]:
                os.lchown(name, self.uid, self.gid)
        return dest

    @property
    def trusted_dir(self) -> Path:
        """A root-only folder of this box (mode 0700, under the work root that bwrap hides from student processes),
        removed by close(): for the trusted processes' ROS logs and private sockets."""
        return self._box_dir / TRUSTED_ROS_HOME

    def trusted_env(self, env: Dict[str, str]) -> Dict[str, str]:
        """`env` with ROS_HOME and ROS_LOG_DIR in a root-only folder of this box, removed by close(): roscore's
        rosout.log holds every log line of the student's nodes, which must not pile up in root's ~/.ros."""
        ros_home = self.trusted_dir
        return dict(env, ROS_HOME=str(ros_home), ROS_LOG_DIR=str(ros_home / "log"))

    def start_trusted(self, argv: Sequence[str], env: Dict[str, str], log_path: Path,
                      cwd: Optional[Path] = None, commands: bool = False) -> SandboxProcess:
        """Start a grader's command as root inside the box's network namespace, with `env` made `trusted_env`;
        stopped by close() at the latest. With `commands`, its stdin is a pipe the grader writes lines to
        (SandboxProcess.send_line), else /dev/null."""
        self._check_log_path(log_path)
        env = self.trusted_env(env)
        full_argv = (self._netns.enter_argv() + [self._tools["setpriv"], "--pdeathsig", "KILL", "--"] + list(argv))
        with open(log_path, "wb") as log:
            popen = subprocess.Popen(full_argv, env=env, cwd=cwd, stdin=subprocess.PIPE if commands
                                     else subprocess.DEVNULL, stdout=log, stderr=subprocess.STDOUT,
                                     start_new_session=True, text=commands)
        return self._track(SandboxProcess(popen, log_path, sandboxed=False))

    def run_trusted(self, argv: Sequence[str], env: Dict[str, str], log_path: Path,
                    timeout_s: Optional[float] = None, cwd: Optional[Path] = None) -> RunResult:
        process = self.start_trusted(argv, env, log_path, cwd)
        return process.wait(self.limits.wall_s if timeout_s is None else timeout_s)

    def start_student(self, argv: Sequence[str], env: Dict[str, str], log_path: Path,
                      cwd: Optional[Path] = None) -> SandboxProcess:
        """Start an untrusted command as the slot's uid, in bubblewrap, with the limits, in the box's network
        namespace. `env` is the ROS environment to run with; `student_env` points HOME and ROS_HOME into the
        workspace. `cwd` (inside the sandbox) defaults to the workspace."""
        self._check_log_path(log_path)
        jail_argv = self._netns.enter_argv() + self._drop_privileges_argv() + self._limits_argv()
        read_fd, write_fd = os.pipe()
        try:
            log = CappedLog(read_fd, log_path, self.limits.output_bytes)  # owns read_fd from here on
        except BaseException:
            os.close(read_fd)
            os.close(write_fd)
            raise
        passwd_fd = os.memfd_create("passwd")
        try:
            os.write(passwd_fd, passwd_with_student(self.uid, self.gid, self.workspace))
            os.lseek(passwd_fd, 0, os.SEEK_SET)
            jail_argv += [self._tools["bwrap"]] + bwrap_args(
                lab_root=self.lab_root, work_root=self.work_root, workspace=self.workspace,
                cwd=Path(cwd) if cwd else self.workspace, tmp_bytes=self.limits.tmp_bytes, passwd_fd=passwd_fd)
            popen = subprocess.Popen(jail_argv + ["--"] + list(argv), env=self.student_env(env), cwd="/",
                                     stdin=subprocess.DEVNULL, stdout=write_fd, stderr=write_fd,
                                     pass_fds=(passwd_fd,))
        finally:
            os.close(write_fd)  # the log reader sees the end of output once the sandbox's copies close too
            os.close(passwd_fd)
        return self._track(SandboxProcess(popen, log_path, sandboxed=True, log=log))

    def run_student(self, argv: Sequence[str], env: Dict[str, str], log_path: Path,
                    timeout_s: Optional[float] = None, cwd: Optional[Path] = None) -> RunResult:
        process = self.start_student(argv, env, log_path, cwd)
        return process.wait(self.limits.wall_s if timeout_s is None else timeout_s)

    def student_processes(self) -> List[int]:
        """Pids (host view) of every live process of the slot's uid."""
        return procfs.processes_of_uid(self.uid)

    def _check_log_path(self, log_path: Path) -> None:
        """Logs are written by root: never in the workspace, where the student could plant a symlink (judged on
        the path as written and as resolved)."""
        if any(is_inside(Path(path), self.workspace) for path in (os.path.abspath(log_path),
                                                                  os.path.realpath(log_path))):
            raise SandboxError("the log {} must not be inside the student's workspace".format(log_path))

    def _drop_privileges_argv(self) -> List[str]:
        return [self._tools["setpriv"], "--reuid={}".format(self.uid), "--regid={}".format(self.gid),
                "--clear-groups", "--no-new-privs", "--inh-caps=-all", "--bounding-set=-all", "--"]

    def _limits_argv(self) -> List[str]:
        limits = self.limits
        return [self._tools["prlimit"],
                "--cpu={}:{}".format(limits.cpu_s, limits.cpu_s + CPU_HARD_GRACE_S),
                "--as={}".format(limits.memory_bytes),
                "--nproc={}".format(limits.processes),
                "--fsize={}".format(limits.file_bytes),
                "--nofile={}".format(limits.open_files),
                "--core=0", "--", self._tools["nice"], "-n", str(STUDENT_NICENESS)]

    def _track(self, process: SandboxProcess) -> SandboxProcess:
        self._processes.append(process)
        return process

    def close(self) -> None:
        """End everything of the box (see the module docstring); SandboxError if something would not die. Safe to
        call twice."""
        problems = []
        for process in self._processes:
            if process.running():
                process.kill()
        self._processes.clear()
        if self._namespace is not None:
            holder = self._netns.pid
            left = procfs.kill_until_gone(
                lambda: [pid for pid in procfs.processes_in_net_namespace(self._namespace) if pid != holder],
                KILL_TIMEOUT_S)
            if left:
                problems.append("processes {} in the box's network namespace would not die".format(left))
        if self._lock_fd is not None:
            left = self._kill_slot_uid()
            if left:
                problems.append("processes {} of uid {} would not die".format(left, self.uid))
        if self._netns is not None:
            self._netns.stop()
            self._netns = None
            self._namespace = None
        if self._workspace_mounted:
            try:
                unmount(self.workspace)
                self._workspace_mounted = False
            except (SandboxError, OSError, subprocess.TimeoutExpired) as error:
                problems.append(str(error))
        if self._box_dir is not None and not self._workspace_mounted:
            shutil.rmtree(self._box_dir, ignore_errors=True)   # never through a workspace still mounted
            self._box_dir = None
        if self._lock_fd is not None:
            os.close(self._lock_fd)  # releases the slot
            self._lock_fd = None
        if problems:
            raise SandboxError("slot {}: {}".format(self.slot, "; ".join(problems)))

    def _kill_slot_uid(self) -> List[int]:
        return procfs.kill_until_gone(self.student_processes, KILL_TIMEOUT_S)


def is_inside(path: Path, folder: Path) -> bool:
    """`path` is `folder` or below it (both taken as they are: resolve them first)."""
    folder = Path(os.path.realpath(folder))
    return path == folder or folder in path.parents


def check_searchable(folder: Path) -> None:
    """The student's uid must be able to walk down to its workspace (bwrap binds it as that uid): the work root
    and each folder above it need the execute bit for others."""
    for path in [folder] + list(folder.parents):
        if not os.stat(path).st_mode & stat.S_IXOTH:
            raise SandboxError("{} is not searchable by other users (chmod o+x), so the sandbox's uid cannot reach "
                               "its workspace under the work root {}".format(path, folder))
