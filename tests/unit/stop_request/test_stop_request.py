"""StopRequest: Ctrl-C and SIGTERM set its flag, and start `on_stop` once, in a thread other than the one the
signal interrupted."""
import os
import signal
import threading

import pytest

from stop_request import STOP_SIGNALS, StopRequest


@pytest.fixture
def restore_handlers():
    """Put back the test process's own SIGINT and SIGTERM handlers afterwards."""
    saved = {signum: signal.getsignal(signum) for signum in STOP_SIGNALS}
    yield
    for signum, handler in saved.items():
        signal.signal(signum, handler)


def test_nothing_is_requested_before_a_signal(restore_handlers):
    stop = StopRequest()
    stop.install()
    assert not stop.is_set()
    assert stop.wait(0.01) is False


@pytest.mark.parametrize("signum", STOP_SIGNALS)
def test_a_signal_sets_the_flag(restore_handlers, signum):
    stop = StopRequest()
    stop.install()
    os.kill(os.getpid(), signum)
    assert stop.wait(5.0)
    assert stop.is_set()


def test_on_stop_runs_once_in_a_thread_of_its_own_while_the_interrupted_thread_holds_a_lock(restore_handlers):
    held = threading.Lock()
    calls = []

    def on_stop():
        with held:   # waits for the interrupted main thread to let go, as the last publish does
            calls.append(threading.current_thread())

    stop = StopRequest(on_stop=on_stop)
    stop.install()
    with held:
        os.kill(os.getpid(), signal.SIGINT)
        os.kill(os.getpid(), signal.SIGTERM)
        assert stop.wait(5.0)
        assert calls == []
    threads = [t for t in threading.enumerate() if t.name == "stop_request"]
    for thread in threads:
        thread.join(5.0)
    assert len(calls) == 1
    assert calls[0] is not threading.main_thread()
