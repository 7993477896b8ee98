#!/usr/bin/env python3
"""Call /movement with the move given on the command line: movement_client.py "Turn Right"."""
import sys

import rospy
from custom_interfaces.srv import MyCustomServiceMessage

from movement_pkg.moves import MOVEMENTS
from tb3_client.waiting import wait_politely

USAGE = 'usage: rosrun movement_pkg movement_client.py "<move>"   (one of: {})'.format(", ".join(MOVEMENTS))

if __name__ == "__main__":
    arguments = rospy.myargv(sys.argv)[1:]
    if len(arguments) != 1:
        print(USAGE, file=sys.stderr)
        sys.exit(1)
    rospy.init_node("movement_client")
    try:
        wait_politely("/movement")
        response = rospy.ServiceProxy("/movement", MyCustomServiceMessage)(arguments[0])
    except (rospy.ROSInterruptException, rospy.ServiceException) as error:
        print("The call to /movement failed: {}".format(error), file=sys.stderr)
        sys.exit(1)
    print("Result of the call to /movement: success = {}".format(response.success))
