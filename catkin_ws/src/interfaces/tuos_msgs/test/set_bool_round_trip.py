#!/usr/bin/env python3
"""rostest: a tuos_msgs/SetBool call reaches a rospy server and its reply comes back field for field."""
import unittest

import rospy
import rostest
from tuos_msgs.srv import SetBool


class SetBoolRoundTrip(unittest.TestCase):
    def setUp(self):
        rospy.wait_for_service("echo_set_bool", timeout=20)
        self.call = rospy.ServiceProxy("echo_set_bool", SetBool)

    def test_true_is_echoed(self):
        reply = self.call(request_signal=True)
        self.assertTrue(reply.response_signal)
        self.assertEqual(reply.response_message, "received True")

    def test_false_is_echoed(self):
        reply = self.call(False)
        self.assertFalse(reply.response_signal)
        self.assertEqual(reply.response_message, "received False")


if __name__ == "__main__":
    rospy.init_node("set_bool_round_trip")
    rostest.rosrun("tuos_msgs", "set_bool_round_trip", SetBoolRoundTrip)
