"""Occupancy grids as ROS lays them out: geometry (resolution, origin, size) and the map_server file formats."""
