#!/usr/bin/env python3
"""scan_client.py [DIRECTION]: prints the LiDAR distance at DIRECTION degrees (default 0, straight ahead)
five times a second, from the my_service service of scan_server.py.

While the service is missing or cannot answer yet (no /scan), it says why every few seconds and keeps
trying; a DIRECTION outside 0..359 prints the usage and exits with 1.
"""
import sys

import rospy

from beginner_tutorials.errors import UsageError
from beginner_tutorials.scan_lookup import parse_direction, usage
from beginner_tutorials.srv import gazebo_server

PRINT_RATE_HZ = 5
COMPLAINT_PERIOD_S = 2.0


class ScanClient:
    def __init__(self, direction):
        self.direction = direction
        self.get_distance = rospy.ServiceProxy("my_service", gazebo_server)

    def run(self):
        rate = rospy.Rate(PRINT_RATE_HZ)
        while not rospy.is_shutdown():
            try:
                distance = self.get_distance(self.direction).distance
                print("distance at {} degrees: {:.3f} m".format(self.direction, distance), flush=True)
            except rospy.ServiceException as error:
                rospy.logwarn_throttle(COMPLAINT_PERIOD_S, "my_service cannot answer yet: {}".format(error))
            rate.sleep()


def main():
    try:
        direction = parse_direction(rospy.myargv(argv=sys.argv)[1:])
    except UsageError as error:
        print("error: {}\n{}".format(error, usage("scan_client.py")), file=sys.stderr)
        return 1
    rospy.init_node("scan_client")
    try:
        ScanClient(direction).run()
    except rospy.ROSInterruptException:
        pass
    return 0


if __name__ == "__main__":
    sys.exit(main())
