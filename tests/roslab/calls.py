"""Service calls that run while the test does something else (injects a fault, makes a second call)."""
import threading
import time

import rospy


class BackgroundCall:
    """One service call on a daemon thread. After `join`, `reply` holds the response (or `error` the
    ServiceException) and `answered_at` the time.monotonic() of the answer."""

    def __init__(self, name, srv_type, *args):
        self.reply = self.error = self.answered_at = None
        self._thread = threading.Thread(target=self._run, args=(name, srv_type, args), daemon=True)
        self._thread.start()

    def _run(self, name, srv_type, args):
        try:
            self.reply = rospy.ServiceProxy(name, srv_type)(*args)
        except rospy.ServiceException as error:
            self.error = error
        self.answered_at = time.monotonic()

    def running(self):
        return self._thread.is_alive()

    def join(self, timeout_s):
        """Wait up to `timeout_s` for the answer; True when it came."""
        self._thread.join(timeout=timeout_s)
        return not self._thread.is_alive()

    def __repr__(self):
        return "BackgroundCall(reply={!r}, error={!r})".format(self.reply, self.error)
