"""Ctrl-C and SIGTERM end the simulator from its own loop, never from inside the signal handler.

rospy's own handler runs its whole shutdown (closing every topic) inside the signal handler, on top of whatever
the main thread was doing. When that is a publish closing a vanished subscriber's connection, which logs, the
handler waits for the topic manager's lock while a rospy thread holding that lock waits for the logging lock
the interrupted main thread holds: the node hangs for ever, ignoring further Ctrl-C and SIGTERM (seen when
roslaunch stopped the simulator right after a client node exited). Here the handler only sets a flag; the loop
sees it between two steps, and rospy shuts down from the main thread.
"""

import signal
import threading

STOP_SIGNALS = (signal.SIGINT, signal.SIGTERM)


class StopRequest:
    """A flag that Ctrl-C or SIGTERM sets once `install()` has replaced the handlers (call it in the main
    thread, after rospy.init_node(..., disable_signals=True))."""

    def __init__(self):
        self._event = threading.Event()

    def install(self):
        for signum in STOP_SIGNALS:
            signal.signal(signum, self._on_signal)

    def _on_signal(self, _signum, _frame):
        self._event.set()

    def is_set(self):
        return self._event.is_set()
