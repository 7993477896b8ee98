#!/usr/bin/env python3
"""The movement client: one word calls /movement, three arguments call /move, and it prints the result.

    rosrun movement_pkg movement_client "Turn Right"     # /movement: "Turn Right", "Turn Left" or "Stop"
    rosrun movement_pkg movement_client left 0.2 5       # /move: direction, velocity, time in seconds

It waits politely until the service exists. Exit code 1 for bad arguments or a failed call.
"""
import sys

import rospy
from custom_interfaces.srv import Move, MyCustomServiceMessage

from movement_pkg.client_request import USAGE, client_request
from movement_pkg.moves import InvalidRequest
from tb3_client.waiting import wait_politely

SERVICE_TYPES = {"/movement": MyCustomServiceMessage, "/move": Move}

if __name__ == "__main__":
    try:
        request = client_request(rospy.myargv(sys.argv)[1:])
    except InvalidRequest as error:
        print("{}\n{}".format(error, USAGE), file=sys.stderr)
        sys.exit(1)
    rospy.init_node("movement_client")
    try:
        wait_politely(request.service)
        response = rospy.ServiceProxy(request.service, SERVICE_TYPES[request.service])(*request.fields)
    except (rospy.ROSInterruptException, rospy.ServiceException) as error:
        print("The call to {} failed: {}".format(request.service, error), file=sys.stderr)
        sys.exit(1)
    print("Result of the call to {}: success = {}".format(request.service, response.success))
