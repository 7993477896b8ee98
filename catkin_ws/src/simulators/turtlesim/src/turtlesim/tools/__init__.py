"""Terminal input for turtle_teleop_key."""
