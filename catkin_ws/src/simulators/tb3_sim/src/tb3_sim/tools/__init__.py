"""Command-line tools over the ROS interface (spawn_box, spawn_model) and the core benchmark."""
