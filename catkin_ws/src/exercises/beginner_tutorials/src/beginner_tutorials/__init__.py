"""The logic behind the beginner_tutorials nodes, in plain Python (no node, no master needed): argument
checks, the add_two_int sum, the /scan lookup, the counter's progress, quaternion helpers and the parameter
demo's table. The nodes in ../../nodes wire these to ROS; the unit tests call them directly."""
