"""Ctrl-C and SIGTERM as a request the node answers from its own threads, never from inside the signal handler.

rospy's own handler runs the node's whole shutdown inside the signal handler, on top of whatever the main
thread was doing, and that deadlocks when the main thread held a lock the shutdown needs:
- a publish in the main thread holds its connection's queue lock (rospy's QueuedConnection.write_data, not
  re-entrant); a shutdown hook publishing a last zero Twist on the same topic then waits for it for ever.
  turtlebot3_drive publishes 125 times per simulated second; at 10x real time on a loaded 2-core machine, 3
  Ctrl-Cs in 195 hung it until roslaunch's SIGKILL, with the robot still driving (0 in 80 with this module);
- a publish closing a vanished subscriber's connection logs: the handler waits for the topic manager's lock
  while a rospy thread holding it waits for the logging lock the interrupted main thread holds (tb3_sim,
  stopped by roslaunch right after a client node exited).
Here the handler only sets a flag, and starts `on_stop` (if given) in a thread of its own: the main thread
finishes what it was doing, releasing its locks, while `on_stop` stops the robot and shuts rospy down. Nodes
that check the flag between two steps of their own loop need no `on_stop`.

Call `install()` in the main thread; start rospy with `rospy.init_node(..., disable_signals=True)`.
"""
import signal
import threading

STOP_SIGNALS = (signal.SIGINT, signal.SIGTERM)


class StopRequest:
    """A flag that Ctrl-C or SIGTERM sets once `install()` has replaced their handlers; the first signal also
    starts `on_stop()` in a new thread (the process waits for that thread before it exits)."""

    def __init__(self, on_stop=None):
        self._event = threading.Event()
        self._on_stop = on_stop

    def install(self):
        for signum in STOP_SIGNALS:
            signal.signal(signum, self._on_signal)

    def _on_signal(self, _signum, _frame):
        if self._event.is_set():
            return
        self._event.set()
        if self._on_stop is not None:
            threading.Thread(target=self._on_stop, name="stop_request").start()

    def is_set(self):
        return self._event.is_set()

    def wait(self, timeout_s):
        """Sleep up to `timeout_s` (wall clock); True as soon as a stop is requested."""
        return self._event.wait(timeout_s)
