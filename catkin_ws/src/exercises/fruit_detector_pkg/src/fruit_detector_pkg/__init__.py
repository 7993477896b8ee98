"""fruit_detector_pkg: what the LiDAR says about a fruit request, as text (plain Python)."""
