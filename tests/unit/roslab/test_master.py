"""RosMaster: a core that fails to start (or is interrupted) while starting leaves no process behind: the master
it already started is ended before the error reaches the test."""
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
    monkeypatch.setattr(master_module, "find_node", lambda package, node: [str(tmp_path / "no_rosout_here")])
    with pytest.raises(OSError):
        master_module.RosMaster(tmp_path)
    assert [process.command[0] for process in started] == ["rosmaster"]
    assert not started[0].running()
