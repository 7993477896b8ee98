#!/usr/bin/env python3
"""add_two_int_client.py A B: asks the add_two_int service for A + B and prints "A + B = SUM".

Wrong arguments (not two integers in the int64 range) print the reason and the usage and exit with 1;
so does a missing service (after SERVICE_WAIT_S) or a refused request, with the server's reason.
"""
import sys

import rospy

from beginner_tutorials.addition import parse_addends, usage
from beginner_tutorials.errors import UsageError
from beginner_tutorials.srv import add_two_int

SERVICE_NAME = "add_two_int"
SERVICE_WAIT_S = 10.0


def add_two_int_client(a, b):
    rospy.wait_for_service(SERVICE_NAME, timeout=SERVICE_WAIT_S)
    add = rospy.ServiceProxy(SERVICE_NAME, add_two_int)
    return add(a, b).sum


def main():
    program = "add_two_int_client.py"
    try:
        a, b = parse_addends(rospy.myargv(argv=sys.argv)[1:])
    except UsageError as error:
        print("error: {}\n{}".format(error, usage(program)), file=sys.stderr)
        return 1
    print("Requesting {} + {}".format(a, b))
    try:
        total = add_two_int_client(a, b)
    except rospy.ServiceException as error:
        print("error: {}".format(error), file=sys.stderr)
        return 1
    except rospy.ROSException as error:
        print("error: {} (is add_two_int_server running?)".format(error), file=sys.stderr)
        return 1
    print("{} + {} = {}".format(a, b, total))
    return 0


if __name__ == "__main__":
    sys.exit(main())
