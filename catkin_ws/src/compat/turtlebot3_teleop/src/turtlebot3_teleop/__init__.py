"""Keyboard teleoperation of a TurtleBot3 with the name, keys, limits and output of ROBOTIS's
turtlebot3_teleop (noetic): keyboard_teleop (the logic), key_terminal (raw keys), ros_node (the node)."""
