"""The ROS 1 layer (the only modules that import rospy): turtlesim_node, turtle_teleop_key, mimic, draw_square."""
