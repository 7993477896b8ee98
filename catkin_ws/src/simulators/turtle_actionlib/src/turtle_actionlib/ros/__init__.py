"""The ROS 1 layer of shape_server and shape_client (the only modules that import rospy)."""
