#!/usr/bin/env python3
"""Logs every message it hears on chatter (std_msgs/String)."""
import rospy
from std_msgs.msg import String


class Listener:
    def __init__(self):
        self.subscriber = rospy.Subscriber("chatter", String, self.on_message)

    def on_message(self, message):
        rospy.loginfo("%s I heard %s", rospy.get_caller_id(), message.data)


def main():
    rospy.init_node("listener", anonymous=True)
    Listener()
    rospy.spin()


if __name__ == "__main__":
    main()
