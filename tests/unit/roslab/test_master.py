"""RosMaster: a core that fails to start (or is interrupted) while starting leaves no process behind: the master
it already started is ended before the error reaches the test. node_path finds the file rosrun would run."""
import subprocess

import pytest

from roslab import master as master_module


def test_a_core_that_fails_after_rosmaster_started_ends_rosmaster(tmp_path, monkeypatch):
    started = []
    real_start = master_module.RosMaster.start

    def start(self, command, label):
        process = real_start(self, command, label)
        started.append(process)
        return process

    monkeypatch.setattr(master_module.RosMaster, "start", start)
    monkeypatch.setattr(master_module, "find_node", lambda package, node, rospack: [str(tmp_path / "no_rosout_here")])
    with pytest.raises(OSError):
        master_module.RosMaster(tmp_path)
    assert [process.command[0] for process in started] == ["rosmaster"]
    assert not started[0].running()


@pytest.mark.parametrize("package, executable", [
    ("lab_web", "web_server"),                        # a devel-space relay and the script it runs: the relay
    ("beginner_tutorials", "add_two_int_server_cpp"),  # a C++ node in devel/lib
    ("client_pkg", "service_client.py"),               # a script in the source folder only
])
def test_node_path_is_the_file_rosrun_runs(package, executable):
    rosrun = subprocess.run(["rosrun", "--prefix", "echo", package, executable], capture_output=True, text=True)
    assert master_module.node_path(package, executable) == rosrun.stdout.split()[0]


def test_node_path_names_a_missing_executable():
    with pytest.raises(FileNotFoundError, match="rosrun client_pkg no_such_node.py: 0 executables found"):
        master_module.node_path("client_pkg", "no_such_node.py")
