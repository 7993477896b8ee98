"""The student's workspace as a tmpfs of a fixed size: a cap on the whole work folder, not just on one file.

RLIMIT_FSIZE only caps each file a process writes (Limits.file_bytes): a submission writing 2 GB as eight files
of 256 MB filled the grader's disk. Mounted as a tmpfs of `size_bytes`, the workspace (its sources, build,
devel, ROS logs and whatever its nodes write) cannot grow past that: a write beyond it fails with ENOSPC ("No
space left on device"), which a build or node reports as it would on a full disk. It is memory-backed, like the
box's /tmp, and only what is written takes memory; `mount` and `umount` come from Debian's mount package.

The mount is made in the grader's (the host's) mount namespace, so bubblewrap binds it like any folder. A grader
that is killed leaves its mounts behind: `stale_mounts` finds them so the next sandbox of the slot removes them.
"""
import subprocess
from pathlib import Path
from typing import List

from lab_grader.errors import SandboxError
from lab_grader.netns import find_tool

MOUNTINFO = Path("/proc/self/mountinfo")
TOOL_TIMEOUT_S = 30.0


def _run(argv: List[str], what: str) -> None:
    result = subprocess.run(argv, stdin=subprocess.DEVNULL, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                            timeout=TOOL_TIMEOUT_S)
    if result.returncode != 0:
        raise SandboxError("could not {}: {}".format(what, result.stdout.decode(errors="replace").strip()))


def mount_workspace(path: Path, size_bytes: int, uid: int, gid: int, mode: int) -> None:
    """Mount a tmpfs of `size_bytes` on the folder `path`, owned by `uid`:`gid` with `mode` (no setuid files,
    no device files)."""
    options = "size={},uid={},gid={},mode={:o},nosuid,nodev".format(size_bytes, uid, gid, mode)
    _run([find_tool("mount"), "-t", "tmpfs", "-o", options, "lab_grader-workspace", str(path)],
         "mount the workspace {} (the sandbox needs root's mount)".format(path))


def unmount(path: Path) -> None:
    """Detach the mount at `path` (lazily: a process still inside only delays the freeing of its memory)."""
    _run([find_tool("umount"), "--lazy", str(path)], "unmount the workspace {}".format(path))


def _unescape(field: str) -> str:
    """A mountinfo path field: spaces, tabs, newlines and backslashes are written as octal escapes."""
    return field.encode().decode("unicode_escape").encode("latin-1").decode(errors="surrogateescape")


def mount_points() -> List[Path]:
    """Every mount point this process sees (field 5 of /proc/self/mountinfo)."""
    return [Path(_unescape(line.split(" ")[4])) for line in MOUNTINFO.read_text().splitlines()]


def stale_mounts(work_root: Path, box_prefix: str, workspace_name: str) -> List[Path]:
    """Workspace mounts `<work_root>/<box_prefix>*/<workspace_name>` left behind by a grader that was killed."""
    return [point for point in mount_points()
            if point.name == workspace_name and point.parent.parent == work_root
            and point.parent.name.startswith(box_prefix)]
