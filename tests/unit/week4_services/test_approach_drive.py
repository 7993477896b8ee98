"""The approach's drive loop (week4_services.approach_drive) that the Week 4 approach service and Part 5's Search
server share, driven by a scripted robot: a point on a line toward a wall that ramps its speed at 1 m/s^2 toward the
command (like the simulated Waffle), /odom at 30 Hz and a LiDAR sweep every sixth update, as real messages."""
import math

import pytest
from nav_msgs.msg import Odometry
from sensor_msgs.msg import LaserScan

from tb3_client.robot import Reading, RobotLost
from week4_services.approach import Outcome
from week4_services.approach_drive import ApproachDrive
from week4_services.requests import approach

ODOM_DT = 1.0 / 30
SWEEP_EVERY = 6
BEAMS = 360


class ScriptedRobot:
    """Drives along +x toward a wall at `wall_m`; every wait_for_update is one /odom step."""

    def __init__(self, wall_m, lose_after_steps=None):
        self.wall_m, self.lose_after_steps = wall_m, lose_after_steps
        self.x = self.speed = self.command = 0.0
        self.steps = self.scan_count = 0
        self.stopped = 0
        self.odom = self._odom()
        self.scan = self._scan()

    def _odom(self):
        odom = Odometry()
        odom.pose.pose.position.x = self.x
        odom.twist.twist.linear.x = self.speed
        odom.header.stamp.secs, odom.header.stamp.nsecs = divmod(int(round(self.steps * ODOM_DT * 1e9)), 10 ** 9)
        return odom

    def _scan(self):
        scan = LaserScan(angle_min=0.0, angle_increment=2 * math.pi / BEAMS, range_min=0.12, range_max=3.5)
        distance = self.wall_m - self.x
        scan.ranges = [distance / math.cos(i * scan.angle_increment) if math.cos(i * scan.angle_increment) > 0.5
                       else float("inf") for i in range(BEAMS)]
        scan.header.stamp = self.odom.header.stamp
        return scan

    def now(self):
        return self.steps * ODOM_DT

    def wait_for_update(self, need_scan=False):
        if self.lose_after_steps is not None and self.steps >= self.lose_after_steps:
            raise RobotLost("no /scan for 1 s")
        self.speed += max(-ODOM_DT, min(ODOM_DT, self.command - self.speed))
        self.x += self.speed * ODOM_DT
        self.steps += 1
        self.odom = self._odom()
        if self.steps % SWEEP_EVERY == 0:
            self.scan, self.scan_count = self._scan(), self.scan_count + 1

    def wait_for_new_sweep(self):
        seen = self.scan_count
        while self.scan_count == seen:
            self.wait_for_update(need_scan=True)

    def latest(self):
        return Reading(self.odom, self.scan, self.scan_count)

    def drive(self, linear, angular):
        self.command = linear

    def stop(self):
        self.command, self.stopped = 0.0, self.stopped + 1


def test_drives_until_the_object_is_at_the_requested_distance_reporting_each_sweep():
    robot = ScriptedRobot(wall_m=1.2)
    heard = []
    drive = ApproachDrive(robot, approach(0.4, 0.1))
    assert drive.travelled() == 0.0
    outcome = drive.run(robot.now, on_sweep=heard.append)
    assert outcome is Outcome.ARRIVED
    while robot.speed > 0:      # the caller stops it; the controller already commands 0
        robot.wait_for_update()
    assert robot.wall_m - robot.x == pytest.approx(0.4, abs=0.01)
    assert len(heard) > 20 and heard == sorted(heard) and heard[0] < 0.01 and heard[-1] > 0.7
    assert drive.start.pose.pose.position.x == pytest.approx(0.0, abs=0.01)   # the sweep after the call
    assert drive.travelled() == pytest.approx(robot.x)


def test_a_cancel_stops_the_robot_at_once_and_returns_none():
    robot = ScriptedRobot(wall_m=3.0)
    outcome = ApproachDrive(robot, approach(0.4, 0.2)).run(robot.now, cancelled=lambda: robot.now() > 1.0)
    assert outcome is None and robot.stopped == 1 and robot.command == 0.0
    assert 1.0 < robot.now() < 1.1


def test_a_lost_robot_passes_its_error_on_with_the_start_kept():
    robot = ScriptedRobot(wall_m=3.0, lose_after_steps=40)
    drive = ApproachDrive(robot, approach(0.4, 0.1))
    with pytest.raises(RobotLost):
        drive.run(robot.now)
    assert drive.start is not None and drive.travelled() > 0.0
