#!/usr/bin/env python3
"""Broadcast the frame of one turtle: world -> <turtle> from its /<turtle>/pose (private param ~turtle)."""
import sys

import rospy
import tf2_ros

from learning_tf2.ros_frames import transform
from stop_request.closed_topic import publish_unless_shut_down
from turtlesim.msg import Pose


class TurtleFrameBroadcaster:
    def __init__(self, turtle):
        self.turtle = turtle
        self.broadcaster = tf2_ros.TransformBroadcaster()
        self.subscriber = rospy.Subscriber("/{}/pose".format(turtle), Pose, self.on_pose)

    def on_pose(self, pose):
        publish_unless_shut_down(self.broadcaster.sendTransform,
                                 transform("world", self.turtle, pose.x, pose.y, pose.theta))


def main():
    rospy.init_node("tf2_turtle_broadcaster")
    if not rospy.has_param("~turtle"):
        rospy.logfatal("Set the turtle to broadcast: rosrun learning_tf2 tf2_broadcaster.py _turtle:=turtle1")
        sys.exit(1)
    TurtleFrameBroadcaster(rospy.get_param("~turtle"))
    rospy.spin()


if __name__ == "__main__":
    main()
