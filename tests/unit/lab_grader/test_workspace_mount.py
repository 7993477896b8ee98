"""Finding the workspace mounts a killed grader left behind, from /proc/self/mountinfo's escaped mount points."""
from pathlib import Path

from lab_grader import workspace_mount

MOUNTINFO = """\
22 1 0:21 / / rw,relatime - overlay overlay rw
95 22 0:50 / /tmp/lab_grader-x/boxes/slot3-ab12/workspace rw,nosuid,nodev - tmpfs lab_grader-workspace rw,size=1024k
96 22 0:51 / /tmp/lab_grader-x/boxes/slot31-cd34/workspace rw - tmpfs lab_grader-workspace rw
97 22 0:52 / /tmp/lab_grader-x/boxes/slot3-with\\040space/workspace rw - tmpfs lab_grader-workspace rw
98 22 0:53 / /tmp/lab_grader-x/boxes/slot3-ef56/other rw - tmpfs tmpfs rw
"""


def test_stale_workspace_mounts_of_one_slot_are_found(tmp_path, monkeypatch):
    mountinfo = tmp_path / "mountinfo"
    mountinfo.write_text(MOUNTINFO)
    monkeypatch.setattr(workspace_mount, "MOUNTINFO", mountinfo)
    boxes = Path("/tmp/lab_grader-x/boxes")
    assert workspace_mount.stale_mounts(boxes, "slot3-", "workspace") == [
        boxes / "slot3-ab12" / "workspace", boxes / "slot3-with space" / "workspace"]
