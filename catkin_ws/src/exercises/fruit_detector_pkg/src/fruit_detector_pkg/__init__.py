"""fruit_detector_pkg: finding an apple or a banana in a camera image by colour (`fruit_detection`) and the
/detect_fruit_service's request checks and replies (`fruit_request`), in plain Python; nodes/detect_fruit_node.py
wires them to ROS."""
