"""A node that follows /use_sim_time and has no /clock yet: its time stands at 0, and its timers, rospy.Rate and
rospy.sleep wait for ever, with no hint of why (a simulator that ended may have left /use_sim_time set on a roscore
that still runs).

- warn_if_clock_missing: one warning, CLOCK_GRACE_WALL_S after the start, if no /clock has come by then.
- wait_for_clock: the same warning, and before it a wait for the first /clock (up to CLOCK_WAIT_WALL_S), so a node
  started beside its simulator logs its first lines with the simulator's time instead of `0.000000`.

Wall-clock timing on purpose: without /clock, rospy time does not move. A /clock that arrives later (a simulator
started after the node) ends rospy's own waits as usual; the warning has said so already.
"""
import threading
import time

import rospy

CLOCK_GRACE_WALL_S = 5.0
CLOCK_WAIT_WALL_S = 15.0
POLL_WALL_S = 0.01
WARNING = ("/use_sim_time is true but no /clock has arrived for {grace:g} s: this node's time stands at 0 and its "
           "timers and sleeps wait for a simulator. Start one (e.g. roslaunch turtlebot3_gazebo "
           "turtlebot3_empty_world.launch), or, if none should run (a simulator that ended may have left it set), "
           "`rosparam set /use_sim_time false` and restart this node.")


def clock_missing(follows_sim_time, now):
    """True when a node following sim time has still received no /clock (rospy's time is 0 until the first)."""
    return follows_sim_time and now.is_zero()


def _missing_now():
    return not rospy.is_shutdown() and clock_missing(not rospy.rostime.is_wallclock(), rospy.get_rostime())


def _check_after(grace_s):
    time.sleep(grace_s)
    if _missing_now():
        rospy.logwarn(WARNING.format(grace=grace_s))


def warn_if_clock_missing(grace_s=CLOCK_GRACE_WALL_S):
    """Call after rospy.init_node: once `grace_s` wall seconds later, warn if the node follows /use_sim_time and
    no /clock has arrived. Returns the (daemon) thread that checks."""
    thread = threading.Thread(target=_check_after, args=(grace_s,), name="sim_clock_watch", daemon=True)
    thread.start()
    return thread


def wait_for_clock(grace_s=CLOCK_GRACE_WALL_S, wait_s=CLOCK_WAIT_WALL_S):
    """Call after rospy.init_node: under /use_sim_time, return once the first /clock has come, or after `wait_s`
    wall seconds, warning once when none has come within `grace_s`. At once on wall time."""
    started = time.monotonic()
    warned = False
    while _missing_now() and time.monotonic() - started < wait_s:
        if not warned and time.monotonic() - started >= grace_s:
            rospy.logwarn(WARNING.format(grace=grace_s))
            warned = True
        time.sleep(POLL_WALL_S)
