"""learning_tf2: the tf2 tutorial's turtle-following logic (plain Python); nodes/ wires it to ROS."""
