"""Runs the demo tour (demo_tour.TOUR) against the running Week 4 servers and prints the measured table.

Waits for the services, calls each in turn, measures the robot before and after from /odom and /scan, prints
one table, then (with --snapshot) asks the simulator for a top-down PNG of the run through its ~snapshot
service, which writes it to the simulator's ~snapshot_path. Exit code 0 when every call returned, 1 otherwise.
"""
import argparse
import math
import sys

import rospy
from std_srvs.srv import Empty
from tuos_msgs.srv import Approach, SetBool, TimedMovement

from tb3_client.robot import Robot, RobotError
from tb3_client.scan_ahead import closest_ahead
from week4_services.demo_tour import TOUR, Pose, describe_outcome, describe_request, format_table

SERVICE_TYPES = {"/move_service": SetBool, "/timed_move_service": TimedMovement, "/approach_service": Approach}
SNAPSHOT_SERVICE = "/gazebo/snapshot"
FRONT_HALF_WIDTH_DEG = 3.0
WAIT_FOR_SERVICES_S = 60.0


def reply_text(reply):
    fields = [getattr(reply, slot) for slot in reply.__slots__]
    return ", ".join(str(value) for value in fields)


class DemoRunner:
    def __init__(self):
        self.robot = Robot()

    def pose(self):
        self.robot.wait_for_update()
        pose, q = self.robot.odom.pose.pose.position, self.robot.odom.pose.pose.orientation
        yaw = math.atan2(2.0 * (q.w * q.z + q.x * q.y), 1.0 - 2.0 * (q.y ** 2 + q.z ** 2))
        return Pose(pose.x, pose.y, yaw)

    def front_distance(self):
        self.robot.wait_for_new_sweep()
        scan = self.robot.scan
        ahead = closest_ahead(scan.ranges, scan.angle_min, scan.angle_increment, scan.range_min,
                              FRONT_HALF_WIDTH_DEG)
        return ahead.distance if ahead else math.inf

    def run(self):
        for service in SERVICE_TYPES:
            rospy.wait_for_service(service, WAIT_FOR_SERVICES_S)
        self.robot.wait_until_ready(need_scan=True)
        rows = []
        for number, stop in enumerate(TOUR, start=1):
            before = self.pose()
            print("[{}/{}] rosservice call {}".format(number, len(TOUR), describe_request(stop)), flush=True)
            reply = rospy.ServiceProxy(stop.service, SERVICE_TYPES[stop.service])(*stop.args)
            self.robot.wait_until_still()
            after = self.pose()
            front = self.front_distance() if stop.measure == "approach" else math.inf
            rows.append((number, describe_request(stop), reply_text(reply),
                         describe_outcome(stop, before, after, front)))
        print()
        print(format_table(("#", "request", "reply", "measured from /odom and /scan"), rows))


def snapshot():
    """Ask the simulator for a top-down PNG of the world, the robot and its trail."""
    rospy.wait_for_service(SNAPSHOT_SERVICE, 10.0)
    rospy.ServiceProxy(SNAPSHOT_SERVICE, Empty)()


def main(argv=None):
    parser = argparse.ArgumentParser(description="Call each Week 4 service and print what the robot did.")
    parser.add_argument("--snapshot", action="store_true",
                        help="ask the simulator for a top-down PNG of the run at the end")
    args = parser.parse_args(rospy.myargv(argv if argv is not None else sys.argv)[1:])
    rospy.init_node("week4_demo_tour")
    try:
        DemoRunner().run()
        if args.snapshot:
            snapshot()
    except (rospy.ROSException, rospy.ServiceException, RobotError) as error:
        print("demo: {}".format(error), file=sys.stderr)
        return 1
    return 0
