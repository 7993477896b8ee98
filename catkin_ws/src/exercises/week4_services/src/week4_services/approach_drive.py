"""The approach's drive loop, shared by the Week 4 approach service and Part 5's Search action server: drive
straight ahead under the approach controller (week4_services.approach) until it says stop.

`ApproachDrive(robot, plan).run(now)` waits for a LiDAR sweep taken after the call (the world may have been reset or
the robot moved since the last one), notes the /odom message it starts from (`start`), then on every /odom or /scan
update feeds the controller the distance travelled (straight line from `start`), the forward speed and each new
sweep's closest object ahead (LiDAR arc of +-20 degrees), with their stamps, and the time since it started, and
drives at the controller's velocity. It returns the controller's outcome, or None once `cancelled()` is true (the
robot is stopped at once). `on_sweep(travelled_m)` hears each new sweep (the Search server's feedback).

`robot` is a tb3_client.robot.Robot (or anything with its wait_for_new_sweep, odom, latest, drive, stop and
wait_for_update); `now()` is the time in seconds (rospy time in the nodes: sim time under tb3_sim). Errors of the
robot (tb3_client.robot.RobotError: /odom or /scan silent) pass through; `start` stays set for the caller's report.
"""
from typing import Callable, Optional

from tb3_client.robot import object_ahead_in, travelled_between
from week4_services.approach import ApproachController, Outcome


class ApproachDrive:
    def __init__(self, robot, plan):
        self.robot = robot
        self.plan = plan
        self.start = None        # the /odom message the drive started from; None before it started

    def travelled(self, odom=None):
        """Metres (straight line) from `start` to `odom` (default: the robot's latest); 0 before the start."""
        return 0.0 if self.start is None else travelled_between(self.start, odom or self.robot.odom)

    def run(self, now: Callable[[], float], on_sweep: Callable[[float], None] = lambda travelled_m: None,
            cancelled: Callable[[], bool] = lambda: False) -> Optional[Outcome]:
        """Drive until the controller's outcome (returned) or `cancelled()` (None); see the module docstring."""
        self.robot.wait_for_new_sweep()
        controller = ApproachController(self.plan)
        self.start = self.robot.odom
        started_s = now()
        sweeps_seen = None
        while True:
            if cancelled():
                self.robot.stop()
                return None
            odom, scan, scan_count = self.robot.latest()
            travelled = self.travelled(odom)
            controller.on_odometry(travelled, odom.twist.twist.linear.x, odom.header.stamp.to_sec())
            if scan_count != sweeps_seen:
                sweeps_seen = scan_count
                ahead = object_ahead_in(scan)
                controller.on_sweep(ahead.distance if ahead else None, scan.header.stamp.to_sec())
                on_sweep(travelled)
            controller.on_clock(now() - started_s)
            step = controller.step()
            self.robot.drive(step.velocity, 0.0)
            if step.outcome is not Outcome.DRIVING:
                return step.outcome
            self.robot.wait_for_update(need_scan=True)
