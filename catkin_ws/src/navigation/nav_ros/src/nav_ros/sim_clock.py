"""The navigation nodes' cheaper ways of following /clock: periodic work in ROS time from one thread that wakes
only when a task is due (lab_nav.clock_alarm), and /clock followed only while a node needs the time.

Under /use_sim_time the alarm is fed by a second callback on /clock: rospy gives a process's subscribers of one
topic a single connection and deserialises each message once, calling the callbacks in the order they subscribed,
so rospy's own time callback has set the new time when the alarm looks at it, and the alarm costs a comparison per
message where rospy.sleep (and rospy.Timer, rospy.Rate, which sleep with it) wakes its thread at every /clock
message. On wall time (no /use_sim_time) the loop sleeps with rospy.sleep, which is then a plain wall sleep.
"""
import contextlib
import threading

import rospy
import rospy.impl.simtime as simtime
from rosgraph_msgs.msg import Clock

from lab_nav.clock_alarm import Alarm, TimeMovedBackwards

RECHECK_S = 0.5
"""Wall seconds after which a sleeping loop looks at the time and at shutdown even without a tick (rospy.sleep's
own interval): the simulation may be paused, and a shutdown sends no /clock."""
CLOCK_WAIT_S = 1.0
"""Wall seconds ClockOnDemand.running() waits for a /clock message after subscribing again."""


class SimTimeAlarm:
    """An Alarm fed from /clock (None under wall time); `sleep_until(t)` sleeps until ROS time t (seconds)."""

    def __init__(self):
        self._alarm = None
        if not rospy.rostime.is_wallclock():
            self._alarm = Alarm()
            self._subscriber = rospy.Subscriber("/clock", Clock, self._on_clock, queue_size=1)

    def _on_clock(self, message):
        self._alarm.tick(message.clock.to_sec())

    def sleep_until(self, due_s, stopped=rospy.is_shutdown):
        """Sleep until ROS time `due_s` or until stopped() (checked at least every RECHECK_S of wall time under
        sim time); raises rospy.ROSInterruptException on shutdown and rospy.ROSTimeMovedBackwardsException when
        the time goes back, as rospy.sleep does."""
        if self._alarm is None:
            rospy.sleep(max(due_s - rospy.get_time(), 0.0))
            return
        try:
            self._alarm.sleep_until(due_s, rospy.get_time, stopped, RECHECK_S)
        except TimeMovedBackwards as jump:
            raise rospy.ROSTimeMovedBackwardsException(jump.args[0]) from None
        if rospy.is_shutdown():
            raise rospy.ROSInterruptException("ROS shutdown request")


class PeriodicThread:
    """Runs `tasks` (a lab_nav PeriodicTasks) in ROS time from a daemon thread called `name` until shutdown or
    stop(): each due task in turn, then a sleep until the next is due. A failing task is logged, not fatal, so one
    task's bug does not stop the others."""

    def __init__(self, tasks, name):
        self._tasks, self._name = tasks, name
        self._stopped = threading.Event()
        self._alarm = SimTimeAlarm()
        threading.Thread(target=self._run, name=name, daemon=True).start()

    def stop(self):
        """No task runs after the one running now, if any (as rospy.Timer.shutdown)."""
        self._stopped.set()

    def _done(self):
        return self._stopped.is_set() or rospy.is_shutdown()

    def _run(self):
        while not self._done():
            try:
                self._tasks.run_due(rospy.get_time())
                self._alarm.sleep_until(self._tasks.next_due(), self._done)
            except rospy.ROSInterruptException:
                break
            except rospy.ROSTimeMovedBackwardsException:
                continue
            except Exception as error:   # noqa: BLE001 - see the class docstring
                if rospy.is_shutdown():
                    break
                rospy.logerr("%s: periodic task failed: %s", self._name, error)


class ClockOnDemand:
    """/clock received only while a node needs the time, for a node that needs it now and then (map_server stamps a
    map when it loads one and its log lines when it answers; in between it would take 100 /clock messages a sim
    second, about 1 % of a core per sim second, for nothing).

    rospy has no public way to stop following /clock, so this uses its internals (rospy 1.15/1.16's
    rospy.impl.simtime: the `_clock_sub` subscriber init_node makes and its callback `_set_rostime_clock_wrapper`),
    and does nothing when they are missing or the node runs on wall time. While paused, rospy's time stays at the
    last /clock message; `running()` subscribes again and waits (CLOCK_WAIT_S of wall time at most) for a message,
    so the time is current inside it, or the last one known when no simulator publishes (as roscpp's Time::now()
    would be). Calls may overlap (rospy serves each service call in its own thread): the clock stops when the last
    one leaves. The master lists the node as a /clock subscriber only while it runs."""

    def __init__(self):
        self._lock = threading.Lock()
        self._users = 0
        self._paused = False

    def pause(self):
        """Stop receiving /clock unless a `running()` block is in progress; False when it cannot be stopped."""
        with self._lock:
            if self._users or self._paused:
                return self._paused
            subscriber = getattr(simtime, "_clock_sub", None)
            if subscriber is None or not hasattr(simtime, "_set_rostime_clock_wrapper"):
                return False
            subscriber.unregister()
            simtime._clock_sub = None
            self._paused = True
            return True

    @contextlib.contextmanager
    def running(self):
        """The block runs with the clock followed (and the time fresh when it was paused); paused again after."""
        with self._lock:
            self._users += 1
            if self._paused:
                simtime._clock_sub = rospy.topics.Subscriber("/clock", Clock, simtime._set_rostime_clock_wrapper,
                                                             queue_size=1)
                self._paused = False
                try:   # rospy's callback, subscribed first, has set the time when this one returns
                    rospy.wait_for_message("/clock", Clock, CLOCK_WAIT_S)
                except rospy.ROSException:
                    pass
        try:
            yield
        finally:
            with self._lock:
                self._users -= 1
            self.pause()
