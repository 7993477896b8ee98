"""The grader's first check runner starts while the package builds and waits for the simulator itself: with
--wait-service NAME it creates its --started file only once the master lists NAME, and gives up (exit 3, no file,
nothing served) when NAME does not appear in time. No master runs here: the master URI points at a closed port."""
import socket

import pytest

from lab_grader.checks import runner


def closed_port_uri():
    with socket.socket() as probe:
        probe.bind(("127.0.0.1", 0))
        return "http://127.0.0.1:{}".format(probe.getsockname()[1])


def test_without_the_service_the_runner_gives_up_and_creates_no_file(tmp_path, monkeypatch, capsys):
    monkeypatch.setenv("ROS_MASTER_URI", closed_port_uri())
    started = tmp_path / "ros-started"
    assert runner.main(["--suite", "week4", "--serve", "--wait-service", "/gazebo/reset_world", "--wait-s", "0.3",
                        "--started", str(started)]) == 3
    assert not started.exists()
    assert "/gazebo/reset_world not listed by the master after 0.3 s" in capsys.readouterr().err


@pytest.mark.parametrize("half", [["--wait-service", "/gazebo/reset_world"], ["--started", "ros-started"]])
def test_wait_service_and_started_go_together(half, capsys):
    with pytest.raises(SystemExit) as exit_info:
        runner.parse_args(["--suite", "week4", "--serve", *half])
    assert exit_info.value.code == 2 and "go together" in capsys.readouterr().err
