#!/usr/bin/env python3
"""Test fixture: serves /echo_set_bool (tuos_msgs/SetBool) and echoes the request signal back."""
import rospy
from tuos_msgs.srv import SetBool, SetBoolResponse


def reply(request):
    """True comes back as done, False as not done, each with a message naming the signal."""
    return SetBoolResponse(request.request_signal, "received {}".format(request.request_signal))


if __name__ == "__main__":
    rospy.init_node("set_bool_echo_server")
    rospy.Service("echo_set_bool", SetBool, reply)
    rospy.spin()
