"""The ROS 1 layer: the simulator node, the /gazebo/* services, message conversion and the periodic outputs."""
