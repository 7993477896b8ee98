#!/usr/bin/env python3
"""Publishes "hello world <time>" on chatter (std_msgs/String) ten times a second."""
import rospy
from std_msgs.msg import String

PUBLISH_RATE_HZ = 10


class Talker:
    def __init__(self):
        self.publisher = rospy.Publisher("chatter", String, queue_size=10)

    def run(self):
        rate = rospy.Rate(PUBLISH_RATE_HZ)
        while not rospy.is_shutdown():
            text = "hello world {}".format(rospy.get_time())
            rospy.loginfo(text)
            self.publisher.publish(String(data=text))
            rate.sleep()


def main():
    rospy.init_node("talker")
    try:
        Talker().run()
    except rospy.ROSInterruptException:
        pass


if __name__ == "__main__":
    main()
