"""The bubblewrap command line that jails a student's process: what it sees of the file system, and which
namespaces it gets. The mount list is explicit so it can be reviewed line by line:

| inside the sandbox       | what                                                    | why                            |
|--------------------------|---------------------------------------------------------|--------------------------------|
| /usr                     | the host's, read-only                                   | programs, Python, ROS, g++     |
| /bin /sbin /lib /lib64.. | symlinks into /usr, as on the host (merged /usr)        | paths like /bin/sh             |
| /etc                     | the host's, read-only; /etc/passwd gains the student    | resolver, ld.so, ROS config    |
|                          | (so `whoami` and getpwuid() work)                       |                                |
| <lab root>               | the lab checkout, read-only                             | its venv, devel space, sims    |
| /proc                    | a new procfs for the sandbox's own pid namespace        | only its own processes show    |
| /dev                     | a minimal new /dev (null, zero, full, random, urandom,  | no host devices                |
|                          | tty, pts), read-only                                    |                                |
| /dev/shm                 | a new tmpfs of `tmp_bytes`                              | POSIX shared memory, semaphores|
| /tmp                     | a new tmpfs of `tmp_bytes`                              | private scratch space          |
| <work root>              | an empty tmpfs, read-only                               | hides every other submission   |
| <workspace>              | the submission's workspace, read-write                  | its build, logs, ROS_HOME      |

Nothing else of the host exists inside: no /home, /root, /opt, /var, /run, /sys, /work/shared, no other mount.
Everything under the lab root is readable by student code (as by any user of the lab): keep grading secrets and
logs under the work root or outside the lab root.
The order matters: /tmp and the work root are covered before the lab and the workspace are bound back on top
(either may lie below /tmp, e.g. a CI checkout in /tmp; the workspace lies below the work root); then the work
root's cover is made read-only, which does not reach the workspace's own mount. The lab root must not lie inside
the work root (`SubmissionSandbox` checks).

Namespaces: a new user namespace (bwrap runs unprivileged; further user namespaces are disabled inside), pid (the
sandbox is pid 1's tree: its processes cannot see or signal anything outside, and all of them die with it), ipc,
uts (hostname `SANDBOX_HOSTNAME`) and cgroup. The network namespace is NOT new: the process inherits the
submission's loopback-only one, which its trusted roscore shares. `--new-session` stops it from pushing input into
a terminal (TIOCSTI); `--die-with-parent` kills it when the grader goes away.
"""
import os
from pathlib import Path
from typing import List, Optional

SYSTEM_READ_ONLY_DIRS = ("/usr", "/etc")
# On Debian 12 these are symlinks into /usr; on a non-merged system they are bound read-only instead.
TOP_LEVEL_LIB_AND_BIN = ("/bin", "/sbin", "/lib", "/lib32", "/lib64", "/libx32")
SANDBOX_HOSTNAME = "sandbox"
# The work root's cover only holds the mount point of the workspace.
WORK_ROOT_COVER_BYTES = 1024 * 1024
STUDENT_NAME = "student"


def bwrap_args(*, lab_root: Path, work_root: Path, workspace: Path, cwd: Path, tmp_bytes: int,
               passwd_fd: Optional[int] = None) -> List[str]:
    """bwrap's options (without the program path and without the trailing `--` and command)."""
    args = ["--unshare-user", "--disable-userns", "--unshare-pid", "--unshare-ipc", "--unshare-uts",
            "--unshare-cgroup-try", "--hostname", SANDBOX_HOSTNAME, "--die-with-parent", "--new-session"]
    for path in SYSTEM_READ_ONLY_DIRS:
        args += ["--ro-bind", path, path]
    for path in TOP_LEVEL_LIB_AND_BIN:
        if os.path.islink(path):
            args += ["--symlink", os.readlink(path), path]
        elif os.path.isdir(path):
            args += ["--ro-bind", path, path]
    if passwd_fd is not None:
        args += ["--ro-bind-data", str(passwd_fd), "/etc/passwd"]
    args += ["--proc", "/proc",
             "--dev", "/dev",
             "--size", str(tmp_bytes), "--tmpfs", "/dev/shm",
             "--remount-ro", "/dev",
             "--size", str(tmp_bytes), "--tmpfs", "/tmp",
             "--size", str(WORK_ROOT_COVER_BYTES), "--tmpfs", str(work_root),
             "--ro-bind", str(lab_root), str(lab_root),
             "--bind", str(workspace), str(workspace),
             "--remount-ro", str(work_root),
             "--chdir", str(cwd)]
    return args


def passwd_with_student(uid: int, gid: int, home: Path, host_passwd: Path = Path("/etc/passwd")) -> bytes:
    """The host's /etc/passwd plus a line naming the sandbox uid, whose home is its workspace."""
    line = "{}:x:{}:{}:lab_grader sandbox:{}:/bin/sh\n".format(STUDENT_NAME, uid, gid, home)
    content = host_passwd.read_text()
    if content and not content.endswith("\n"):
        content += "\n"
    return (content + line).encode()
