"""PendingCalls: service actions run at the start of the next update, in order, with results and errors handed
back to the waiting callback thread (no ROS)."""
import threading
import time

import pytest

from turtlesim.core.pending_calls import CallAbandoned, PendingCalls


def submit_in_thread(pending, action, *args):
    """Submit from a thread of its own, as rospy runs each service callback; returns the thread and its outcome."""
    outcome = {}

    def run():
        try:
            outcome["result"] = pending.submit(action, *args)
        except Exception as error:
            outcome["error"] = error
    thread = threading.Thread(target=run)
    thread.start()
    return thread, outcome


def fail():
    raise ValueError("an unknown turtle")


def wait_for_queued(pending, count):
    deadline = time.monotonic() + 5
    while len(pending._calls) < count:
        assert time.monotonic() < deadline, "the calls never reached the queue"
        time.sleep(0.001)


def test_a_call_waits_for_the_update_and_gets_its_result():
    pending = PendingCalls(lambda: False)
    thread, outcome = submit_in_thread(pending, lambda a, b: a + b, 2, 3)
    wait_for_queued(pending, 1)
    assert outcome == {}, "nothing runs before the update"
    assert pending.run_all() == 1
    thread.join(5)
    assert outcome == {"result": 5}


def test_calls_run_in_the_order_they_came_and_errors_reach_the_caller():
    pending = PendingCalls(lambda: False)
    ran = []
    first, _ = submit_in_thread(pending, ran.append, "teleport")
    wait_for_queued(pending, 1)
    second, _ = submit_in_thread(pending, ran.append, "clear")
    wait_for_queued(pending, 2)
    failing, outcome = submit_in_thread(pending, fail)
    wait_for_queued(pending, 3)
    assert pending.run_all() == 3
    for thread in (first, second, failing):
        thread.join(5)
    assert ran == ["teleport", "clear"]
    assert isinstance(outcome.get("error"), ValueError), outcome


def test_a_call_is_abandoned_when_no_update_will_come():
    stopped = threading.Event()
    pending = PendingCalls(stopped.is_set)
    thread, outcome = submit_in_thread(pending, lambda: "never")
    wait_for_queued(pending, 1)
    stopped.set()
    thread.join(5)
    assert isinstance(outcome.get("error"), CallAbandoned)
    assert pending.run_all() == 0, "an abandoned call does not run later"


def test_an_update_with_nothing_pending_runs_nothing():
    assert PendingCalls(lambda: False).run_all() == 0


@pytest.mark.parametrize("count", [1, 20])
def test_every_waiting_caller_is_answered_by_one_update(count):
    pending = PendingCalls(lambda: False)
    threads = [submit_in_thread(pending, lambda index=index: index) for index in range(count)]
    wait_for_queued(pending, count)
    pending.run_all()
    for thread, _ in threads:
        thread.join(5)
    assert sorted(outcome["result"] for _, outcome in threads) == list(range(count))
