#!/usr/bin/env python3
"""Add a fixed frame: carrot1, 2 m to turtle1's left (the tutorial's (0, 2, 0)), broadcast at 10 Hz."""
import rospy

from learning_tf2.follow import FIXED_CARROT_OFFSET_M
from learning_tf2.ros_frames import broadcast_carrot

if __name__ == "__main__":
    rospy.init_node("fixed_tf2_broadcaster")
    broadcast_carrot(lambda now_s: FIXED_CARROT_OFFSET_M)
