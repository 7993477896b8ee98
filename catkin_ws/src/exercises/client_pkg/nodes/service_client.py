#!/usr/bin/env python3
"""Call /moving (std_srvs/Empty) once, waiting politely until the service exists, and say so."""
import rospy
from std_srvs.srv import Empty

from tb3_client.waiting import wait_politely

if __name__ == "__main__":
    rospy.init_node("service_client")
    try:
        wait_politely("/moving")
        rospy.ServiceProxy("/moving", Empty)()
        rospy.loginfo("the robot is moving")
    except (rospy.ROSInterruptException, rospy.ServiceException) as error:
        rospy.logerr("could not call /moving: %s", error)
