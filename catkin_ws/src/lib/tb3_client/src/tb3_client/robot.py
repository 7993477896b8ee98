"""The TurtleBot3 as service servers see it: /cmd_vel out, /odom and /scan in, with a watchdog.

Timing is rospy time (simulated under /use_sim_time). Waiting is done in short wall-clock slices so that a
simulator that dies (its /clock and /odom stop) is noticed within STALE_AFTER_WALL_S instead of hanging the
service call forever, which is what a plain rospy.sleep would do once /clock stops.
"""
import contextlib
import math
import threading
import time
from typing import NamedTuple

import rospy
from nav_msgs.msg import Odometry
from sensor_msgs.msg import LaserScan

from master_reconnect import keep_registered
from sim_clock import wait_for_clock
from tb3_client.commands import CommandPublisher
from tb3_client.scan_ahead import closest_ahead

STALE_AFTER_WALL_S = 1.0      # no /odom (or /scan while one is needed) for this long: the robot is gone
FIRST_MESSAGE_GRACE_S = 5.0   # a request right after start-up waits this long for the first /odom and /scan
WAIT_SLICE_WALL_S = 0.01
STILL_SPEED_MPS = 0.002
STILL_TIMEOUT_S = 2.0


class Reading(NamedTuple):
    """The latest /odom and /scan, taken together, and the number of sweeps received so far."""

    odom: Odometry
    scan: LaserScan
    scan_count: int


def travelled_between(start, odom):
    """Straight-line distance (m) between the positions of two odometry messages."""
    here, there = odom.pose.pose.position, start.pose.pose.position
    return math.hypot(here.x - there.x, here.y - there.y)


def object_ahead_in(scan):
    """The closest object within the arc ahead in the sweep `scan` (scan_ahead.ObjectAhead), or None."""
    return closest_ahead(scan.ranges, scan.angle_min, scan.angle_increment, scan.range_min)


class RobotError(RuntimeError):
    """The request cannot be carried out; the text tells the caller why."""


class RobotBusy(RobotError):
    """Another request is still moving the robot."""


class RobotLost(RobotError):
    """The simulator or robot stopped publishing /odom or /scan, or its time went back (it restarted)."""


class Robot:
    """Velocity commands and the latest odometry and LiDAR sweep, each with its wall-clock arrival time.

    Creating it also keeps the node registered across a roscore restart (master_reconnect) and, under
    /use_sim_time, waits for the simulator's first /clock (up to 15 s, warning after 5 s; sim_clock), so the server's
    "ready" line carries sim time rather than 0.000000."""

    def __init__(self):
        self._cmd_vel = CommandPublisher("cmd_vel", queue_size=1)
        self._changed = threading.Condition()
        self._busy = threading.Lock()
        self.odom = None
        self.scan = None
        self.scan_count = 0
        self._odom_wall = None
        self._scan_wall = None
        self._restarts = 0              # times the /odom stamps went back: the simulator restarted or was reset
        self._restarts_at_start = None  # _restarts when the current request started (see exclusive)
        rospy.Subscriber("odom", Odometry, self._on_odom, queue_size=1)
        rospy.Subscriber("scan", LaserScan, self._on_scan, queue_size=1)
        rospy.on_shutdown(self._cmd_vel.stop_for_good)
        keep_registered()
        wait_for_clock()

    def _on_odom(self, msg):
        with self._changed:
            if self.odom is not None and msg.header.stamp < self.odom.header.stamp:
                self._restarts += 1
            self.odom, self._odom_wall = msg, time.monotonic()
            self._changed.notify_all()

    def _on_scan(self, msg):
        with self._changed:
            self.scan, self._scan_wall = msg, time.monotonic()
            self.scan_count += 1
            self._changed.notify_all()

    def drive(self, linear, angular):
        """Publish one velocity command (m/s, rad/s); the robot holds it until the next one. Nothing once the
        node is shutting down: its last command was a zero Twist."""
        self._cmd_vel.publish(linear, angular)

    def stop(self):
        self.drive(0.0, 0.0)

    @contextlib.contextmanager
    def exclusive(self, need_scan=False):
        """Hold the robot for one request: refuses a second concurrent request, checks the robot is alive
        first, and always stops the robot at the end, whatever happened."""
        if not self._busy.acquire(blocking=False):
            raise RobotBusy("the robot is busy with another request; try again when it has finished")
        try:
            self.wait_until_ready(need_scan)
            self._restarts_at_start = self._restarts
            yield self
        finally:
            self._restarts_at_start = None
            self.stop()
            self._busy.release()

    def wait_until_ready(self, need_scan=False):
        """Give a robot that has not published yet (the simulator is still starting) up to
        FIRST_MESSAGE_GRACE_S, then RobotLost unless /odom (and /scan if needed) are arriving and rospy time
        is running. Under /use_sim_time rospy time stays 0 until this node's first /clock message, which can
        come after the first /odom; a duration measured from 0 would end early."""
        deadline = time.monotonic() + FIRST_MESSAGE_GRACE_S
        with self._changed:
            while (self._odom_wall is None or (need_scan and self._scan_wall is None)
                   or rospy.get_rostime().is_zero()) and time.monotonic() < deadline and not rospy.is_shutdown():
                self._changed.wait(WAIT_SLICE_WALL_S)
        if rospy.get_rostime().is_zero():
            raise RobotLost("no /clock for {:.1f} s while /use_sim_time is set: is the simulator running?".format(
                FIRST_MESSAGE_GRACE_S))
        self._check_alive(need_scan)

    def _check_alive(self, need_scan):
        """RobotLost unless /odom (and /scan if needed) arrived within the last STALE_AFTER_WALL_S, and
        (during a request) the /odom stamps have not gone back: a respawned or reset simulator starts its
        clock again from 0, possibly within STALE_AFTER_WALL_S, and a request measured on the old clock would
        otherwise wait on the new one."""
        if self._restarts_at_start is not None and self._restarts != self._restarts_at_start:
            raise RobotLost("simulated time went back to {:.1f} s: the simulator restarted or was reset".format(
                self.odom.header.stamp.to_sec()))
        now = time.monotonic()
        for name, arrived, needed in (("/odom", self._odom_wall, True), ("/scan", self._scan_wall, need_scan)):
            if needed and (arrived is None or now - arrived > STALE_AFTER_WALL_S):
                raise RobotLost("no {} from the robot for {:.1f} s: is the simulator running?".format(
                    name, STALE_AFTER_WALL_S))

    def perform(self, motion, announce=None):
        """Hold the velocities of `motion` (tb3_client.motion.Motion) for its duration under exclusive(),
        then stop; RobotBusy or RobotLost when that cannot be done. `announce` is logged once the robot is
        held and ready, so a refused call never claims in the log that it is moving."""
        with self.exclusive():
            if announce:
                rospy.loginfo(announce)
            self.drive(motion.linear, motion.angular)
            self.wait(motion.duration_s)

    def wait(self, duration_s, need_scan=False):
        """Wait `duration_s` seconds of rospy time, raising RobotLost if the robot goes quiet meanwhile."""
        end = rospy.get_rostime() + rospy.Duration.from_sec(duration_s)
        while rospy.get_rostime() < end:
            self.wait_for_update(need_scan)

    def wait_for_update(self, need_scan=False):
        """Block until the next /odom or /scan message (or a short slice); RobotLost if they stopped."""
        if rospy.is_shutdown():
            raise RobotError("the node is shutting down")
        with self._changed:
            self._changed.wait(WAIT_SLICE_WALL_S)
        self._check_alive(need_scan)

    def latest(self):
        """The latest /odom and /scan as one Reading: both read at once, so a callback between them cannot
        pair a sweep with odometry from a different moment than the caller thinks."""
        with self._changed:
            return Reading(self.odom, self.scan, self.scan_count)

    def forward_speed(self):
        """Forward speed (m/s) in the body frame, from the latest /odom."""
        return self.odom.twist.twist.linear.x

    def object_ahead(self):
        """The closest object within the arc ahead in the latest sweep (scan_ahead.ObjectAhead), or None."""
        return object_ahead_in(self.scan)

    def wait_until_still(self):
        """After a stop: wait (rospy time, at most STILL_TIMEOUT_S) until /odom reports it has stopped."""
        end = rospy.get_rostime() + rospy.Duration.from_sec(STILL_TIMEOUT_S)
        while rospy.get_rostime() < end and (abs(self.forward_speed()) > STILL_SPEED_MPS
                                            or abs(self.odom.twist.twist.angular.z) > STILL_SPEED_MPS):
            self.wait_for_update()

    def wait_for_new_sweep(self):
        """Block until a LiDAR sweep newer than the current one arrives (RobotLost if /scan stops)."""
        seen = self.scan_count
        while self.scan_count == seen:
            self.wait_for_update(need_scan=True)
