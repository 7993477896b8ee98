#!/usr/bin/env python3
"""Call /moving (std_srvs/Empty) once, waiting politely until the service exists, and say so."""
import rospy
from std_srvs.srv import Empty

from tb3_client.waiting import call_once

if __name__ == "__main__":
    rospy.init_node("service_client")
    call_once("/moving", Empty, "the robot is moving")
