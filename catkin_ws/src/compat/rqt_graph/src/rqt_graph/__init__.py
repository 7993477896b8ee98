"""rqt_graph: the running ROS graph as a picture (dot_graph builds it, main shows or writes it)."""
