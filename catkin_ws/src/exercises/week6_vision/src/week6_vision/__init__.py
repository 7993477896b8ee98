"""COM2009 Assignment #1 Part 6 (vision) model answers: the image helpers their nodes share (colour masks and
centroids, which camera rows see which stretch of floor) and their pure control logic, with no ROS import."""
