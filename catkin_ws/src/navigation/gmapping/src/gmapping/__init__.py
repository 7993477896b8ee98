"""gmapping's slam_gmapping node over lab_nav.slam (ros_node is the only module importing rospy)."""
