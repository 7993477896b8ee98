"""lab_web: the lab in a browser tab (tb3_sim's world, turtlesim's canvas, the ROS graph, teleop and the Week 4
services) for students with no display."""
