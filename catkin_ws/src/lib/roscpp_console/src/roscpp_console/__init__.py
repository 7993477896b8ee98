"""roscpp's console lines for Python nodes: line_format (the format, no ROS import) and handler (rospy's
console handler swapped for one that prints them)."""
