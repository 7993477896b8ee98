#!/usr/bin/env python3
"""Week 4, part 2: call /move_service with request_signal true and print the server's response.

Waits for the service first, so it can be started before the server. Exits 1 with a clear message when the
call fails (the server died, or Ctrl-C while waiting).
"""
import sys

import rospy
from tuos_msgs.srv import SetBool

NODE_NAME = "move_service_client"
SERVICE_NAME = "move_service"


def main():
    rospy.init_node(NODE_NAME)
    rospy.loginfo("Waiting for the '%s' service...", SERVICE_NAME)
    try:
        rospy.wait_for_service(SERVICE_NAME)
        call_move_service = rospy.ServiceProxy(SERVICE_NAME, SetBool)
        response = call_move_service(request_signal=True)
    except (rospy.ServiceException, rospy.ROSInterruptException) as error:
        print("The service call failed: {}".format(error), file=sys.stderr)
        sys.exit(1)
    print("response_signal: {}".format(response.response_signal))
    print("response_message: {}".format(response.response_message))


if __name__ == "__main__":
    main()
