#!/usr/bin/env python3
"""Call /stop (std_srvs/Empty) once, waiting politely until the service exists, and say so."""
import rospy
from std_srvs.srv import Empty

from tb3_client.waiting import wait_politely

if __name__ == "__main__":
    rospy.init_node("stop_client")
    try:
        wait_politely("/stop")
        rospy.ServiceProxy("/stop", Empty)()
        rospy.loginfo("the robot is stopped")
    except (rospy.ROSInterruptException, rospy.ServiceException) as error:
        rospy.logerr("could not call /stop: %s", error)
