"""ROS message conversions and map fetching shared by the navigation nodes."""
