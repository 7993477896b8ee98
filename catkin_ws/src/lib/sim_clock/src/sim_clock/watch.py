"""One warning when a node follows /use_sim_time and no /clock has come: the node's time stands at 0 and its
timers, rospy.Rate and rospy.sleep wait for ever, with no hint of why (a simulator that ended may have left
/use_sim_time set on a roscore that still runs).

Wall-clock timing on purpose: without /clock, rospy time does not move. A /clock that arrives later (a simulator
started after the node) ends the wait as usual; the warning has said so already.
"""
import threading
import time

import rospy

CLOCK_GRACE_WALL_S = 5.0
WARNING = ("/use_sim_time is true but no /clock has arrived for {grace:g} s: this node's time stands at 0 and its "
           "timers and sleeps wait for a simulator. Start one (e.g. roslaunch turtlebot3_gazebo "
           "turtlebot3_empty_world.launch), or, if none should run (a simulator that ended may have left it set), "
           "`rosparam set /use_sim_time false` and restart this node.")


def clock_missing(follows_sim_time, now):
    """True when a node following sim time has still received no /clock (rospy's time is 0 until the first)."""
    return follows_sim_time and now.is_zero()


def _check_after(grace_s):
    time.sleep(grace_s)
    if not rospy.is_shutdown() and clock_missing(not rospy.rostime.is_wallclock(), rospy.get_rostime()):
        rospy.logwarn(WARNING.format(grace=grace_s))


def warn_if_clock_missing(grace_s=CLOCK_GRACE_WALL_S):
    """Call after rospy.init_node: once `grace_s` wall seconds later, warn if the node follows /use_sim_time and
    no /clock has arrived. Returns the (daemon) thread that checks."""
    thread = threading.Thread(target=_check_after, args=(grace_s,), name="sim_clock_watch", daemon=True)
    thread.start()
    return thread
