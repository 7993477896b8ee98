"""rospy's time notifications without Python 3.10+'s deprecation warning: a node calls quiet_time_notifications()
before rospy.init_node.

Why: under /use_sim_time rospy wakes its time sleepers with Condition.notifyAll on every /clock message (100 per
sim second from the simulator, 1000 a wall second at a real-time factor of 10), and since Python 3.10 each call
runs warnings.warn, which matches the message against every warning filter only to ignore it: about half of the
/clock callback's time (py-spy --gil, move_base and amcl at factor 5).
"""
import threading

import rospy.rostime


class _QuietCondition(threading.Condition):
    """A threading.Condition whose notifyAll is notify_all, without the DeprecationWarning Python 3.10+ issues."""

    def notifyAll(self):   # noqa: N802 - the deprecated name rospy calls
        self.notify_all()


def quiet_time_notifications():
    """Make rospy's time updates skip the deprecation warning; call before rospy.init_node. Before init_node no
    thread waits on rospy's condition (rospy.rostime._rostime_cond), so it is replaced by one whose notifyAll is
    notify_all; nothing changes when rospy has no such condition or it was replaced already."""
    if type(getattr(rospy.rostime, "_rostime_cond", None)) is threading.Condition:
        rospy.rostime._rostime_cond = _QuietCondition()
