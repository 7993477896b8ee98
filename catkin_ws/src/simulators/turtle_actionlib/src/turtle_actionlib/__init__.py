"""turtle_actionlib: the Shape action tutorial. `shape_controller` is the polygon controller (no ROS);
`ros` holds shape_server and shape_client."""
