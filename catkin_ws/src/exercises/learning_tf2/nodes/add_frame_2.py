#!/usr/bin/env python3
"""Add a moving frame: carrot1 circles turtle1 at 10 m radius, once every 2 s, broadcast at 10 Hz."""
import rospy

from learning_tf2.follow import moving_carrot_offset
from learning_tf2.ros_frames import broadcast_carrot

if __name__ == "__main__":
    rospy.init_node("dynamic_tf2_broadcaster")
    broadcast_carrot(moving_carrot_offset)
