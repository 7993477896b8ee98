"""A student's output log: stored whole when short; cut at the cap (marker included) and marked truncated when
long, while the rest is still read so the writer never blocks."""
import os
import threading

from lab_grader.sandbox_process import CappedLog

CAP_BYTES = 1000


def write_through_pipe(tmp_path, data, cap=CAP_BYTES):
    read_fd, write_fd = os.pipe()
    log = CappedLog(read_fd, tmp_path / "out.log", cap)
    assert (tmp_path / "out.log").exists(), "the log exists as soon as the reader is set up"
    writer = threading.Thread(target=lambda: (os.write(write_fd, data) if data else None, os.close(write_fd)))
    writer.start()
    writer.join(10)
    log.join(10)
    assert not writer.is_alive(), "the writer never blocked"
    return log, (tmp_path / "out.log").read_bytes()


def test_a_short_output_is_stored_whole(tmp_path):
    log, stored = write_through_pipe(tmp_path, b"hello\n")
    assert stored == b"hello\n" and not log.truncated


def test_no_output_leaves_an_empty_log(tmp_path):
    log, stored = write_through_pipe(tmp_path, b"")
    assert stored == b"" and not log.truncated


def test_a_long_output_is_cut_at_the_cap_with_a_marker_and_fully_drained(tmp_path):
    log, stored = write_through_pipe(tmp_path, b"x" * 5_000_000)
    assert log.truncated and len(stored) <= CAP_BYTES
    assert stored.startswith(b"x" * 500) and stored.endswith(b"capped at 1000 bytes]\n")


def test_a_cap_smaller_than_the_marker_stores_only_output(tmp_path):
    log, stored = write_through_pipe(tmp_path, b"y" * 100, cap=10)
    assert log.truncated and stored == b""
