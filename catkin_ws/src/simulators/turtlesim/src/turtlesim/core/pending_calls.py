"""Service calls held until the start of the next update, as the original handles them (no ROS, no Qt).

The original's update runs `ros::spinOnce()` first, which answers the service calls that arrived since the last
update, then moves and draws the turtles. So a teleport is drawn in the update that follows its call, and a
`/clear` sent right after the teleport's answer comes in the update after that: the teleport's pen line is
cleared, and the canvas comes out clean. The replica's service callbacks run on rospy's threads as the calls
arrive; each hands its action to PendingCalls and waits, and the update runs them all, in order, before it steps.
"""
import threading

WAIT_SLICE_S = 0.1


class CallAbandoned(RuntimeError):
    """The node stopped before the update that would have run the call."""


class _Call:
    def __init__(self, action, args):
        self.action, self.args = action, args
        self.done = threading.Event()
        self.result = None
        self.error = None


class PendingCalls:
    """A queue of actions that `run_all` (the update) executes and `submit` (a callback) waits for."""

    def __init__(self, stopped):
        """`stopped()`: True once no update will come any more; waiting calls then raise CallAbandoned."""
        self._stopped = stopped
        self._lock = threading.Lock()
        self._calls = []

    def submit(self, action, *args):
        """Run `action(*args)` at the start of the next update; its result, or its exception raised here."""
        call = _Call(action, args)
        with self._lock:
            self._calls.append(call)
        while not call.done.wait(WAIT_SLICE_S):
            if self._stopped():
                with self._lock:
                    if call in self._calls:
                        self._calls.remove(call)
                        raise CallAbandoned("turtlesim is shutting down")
        if call.error is not None:
            raise call.error
        return call.result

    def run_all(self):
        """Run every call submitted so far, in the order they came (from the update, before it steps); returns
        how many ran."""
        with self._lock:
            calls, self._calls = self._calls, []
        for call in calls:
            try:
                call.result = call.action(*call.args)
            except Exception as error:   # handed to the waiting callback, which raises it in its own thread
                call.error = error
            call.done.set()
        return len(calls)
