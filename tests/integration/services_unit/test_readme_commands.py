"""Every row of the README's table of the ROS 2 Services unit runs: its ROS 1 command, typed as it stands in
the README, against the unit's simulation (course_sim_services, at real time as the course runs it), in the
table's order. A command either exits 0 showing the row's "you see" text, or keeps running (a server, a launch
file) once it has shown it; those are ended with the module. A `rosservice call` waits until its server (started by an
earlier row) offers the service, as a student would. The rows depend on each other: run the whole module.

Why real time: the rows that move the robot take 17 s of sim time in all (the quiz client's 10 s turn,
movement_client's 5 s, /move's 2 s), and for the rest of the module's minutes the simulator and the servers the
rows start only follow /clock, which costs each node about 1.5 times as much at 3x as at 1x."""
import re
from pathlib import Path

import pytest

from roslab import wait_for_param, wait_for_service, wait_until
from roslab.launch_args import CHEAP_CAMERA

README = Path(__file__).resolve().parents[3] / "README.md"
SECTION = "### The ROS 2 Services unit in ROS 1"
ROW = re.compile(r"^\| `(ros2 [^`]+)` \| `([^`]+)` \| *(?:`([^`]*)`)? *\|$")
SHOWN_WITHIN_S = 60


def readme_rows():
    """(ROS 2 command, ROS 1 command, text the ROS 1 command shows or '') for each row of the table."""
    section = README.read_text().split(SECTION, 1)[1].split("\n### ", 1)[0]
    rows = []
    for line in section.splitlines():
        if line.startswith("| `ros2 "):
            match = ROW.match(line)
            if not match:
                raise ValueError("README: a row of the ROS 2 table is not `ros2 ...` | `ros ...` | `shown`: " + line)
            ros2, ros1, shown = match.groups()
            rows.append((ros2, ros1, shown or ""))
    return rows


def test_the_table_maps_every_row():
    rows = readme_rows()
    assert len(rows) >= 30
    assert all(ros1.split()[0] in {"rosservice", "rossrv", "roslaunch", "rosrun", "rosparam"}
               for _, ros1, _ in rows)


@pytest.fixture(scope="module")
def simulation(ros_master):
    ros_master.roslaunch("course_sim_services", "course_sim_services.launch", "gui:=false", "real_time_factor:=1",
                         *CHEAP_CAMERA)
    assert wait_for_param(ros_master.uri, "/use_sim_time") is True
    wait_for_service(ros_master.uri, "/moving", timeout_s=60)
    return ros_master


@pytest.mark.slow
@pytest.mark.parametrize("ros2, ros1, shown", readme_rows(), ids=[row[1] for row in readme_rows()])
def test_readme_row_runs(simulation, ros2, ros1, shown):
    if ros1.startswith("rosservice call "):
        wait_for_service(simulation.uri, ros1.split()[2], timeout_s=30)   # a server started a row before
    process = simulation.start(["bash", "-c", ros1], ros1.split()[0])
    wait_until(lambda: not process.running() or (shown and shown in process.output()), SHOWN_WITHIN_S,
               "`{}` to show {!r} or exit".format(ros1, shown))
    output = process.output()
    assert shown in output, output
    if not process.running():
        assert process.popen.returncode == 0, output
