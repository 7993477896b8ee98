"""Week 4 ROS Services reference solutions: request validation, the /scan helper and the approach
controller (plain Python); the nodes in nodes/ wire them to ROS."""
