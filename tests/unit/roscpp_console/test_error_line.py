"""The ERROR line map_server and map_saver print before they contact the master, in roscpp's format."""
import re

from roscpp_console.line_format import error_line


def test_an_early_error_is_a_roscpp_console_line_on_stderr(capsys, monkeypatch):
    monkeypatch.delenv("ROSCONSOLE_FORMAT", raising=False)
    error_line("threshold_free must be between 0 and 100")
    captured = capsys.readouterr()
    assert captured.out == ""
    assert re.fullmatch(r"\[ERROR\] \[\d+\.\d{9}\]: threshold_free must be between 0 and 100\n", captured.err)


def test_rosconsole_format_is_followed(capsys, monkeypatch):
    monkeypatch.setenv("ROSCONSOLE_FORMAT", "${severity}: ${message}")
    error_line("usage")
    assert capsys.readouterr().err == "ERROR: usage\n"
