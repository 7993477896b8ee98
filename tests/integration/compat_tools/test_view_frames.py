"""`rosrun tf view_frames` (Debian's tf-tools 1.13.2 crashes before writing the PDF; the compat tf package's tool
does not): with transforms being published it writes frames.gv and frames.pdf into the current folder."""
import subprocess

import pytest

from roslab import wait_for_topic


@pytest.fixture(scope="module")
def transforms(ros_master):
    """A two-level tree on /tf: world -> robot -> sensor, from tf's static_transform_publisher."""
    ros_master.rosrun("tf", "static_transform_publisher", "1", "0", "0", "0", "0", "0", "world", "robot", "50")
    ros_master.rosrun("tf", "static_transform_publisher", "0", "0", "0.5", "0", "0", "0", "robot", "sensor", "50")
    wait_for_topic(ros_master.uri, "/tf")
    return ros_master


def test_view_frames_writes_the_graph_and_the_pdf_in_the_current_folder(transforms, tmp_path):
    result = subprocess.run(["rosrun", "tf", "view_frames"], env=transforms.env, cwd=tmp_path,
                            stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, timeout=90)
    assert result.returncode == 0, result.stdout
    assert "Listening to /tf for 5.0 seconds" in result.stdout and "frames.pdf generated" in result.stdout
    graph = (tmp_path / "frames.gv").read_text()
    assert '"world" -> "robot"' in graph and '"robot" -> "sensor"' in graph
    assert (tmp_path / "frames.pdf").read_bytes().startswith(b"%PDF")
