#!/usr/bin/env python3
"""The quiz's client: ask /turn to spin right at 0.2 rad/s for 10 s, report the result, exit 0 when done
(exit 1 when the call fails or is refused)."""
import sys

import rospy
from services_quiz_srv.srv import Turn

from tb3_client.waiting import wait_politely

REQUEST = ("right", 0.2, 10)

if __name__ == "__main__":
    rospy.init_node("turn_client")
    try:
        wait_politely("/turn")
        response = rospy.ServiceProxy("/turn", Turn)(*REQUEST)
    except (rospy.ROSInterruptException, rospy.ServiceException) as error:
        rospy.logerr("The call to /turn failed: %s", error)
        sys.exit(1)
    rospy.loginfo("Turn %s at %.1f rad/s for %d s: success = %s", *REQUEST, response.success)
    sys.exit(0 if response.success else 1)
