"""Mapping and navigation algorithms, plain Python/numpy with no ROS import (the nodes in gmapping, map_server,
amcl, move_base and explore_lite wire them to topics). Subpackages by layer: `maps` (grid geometry, map files),
`slam`, `localization`, `costmap`, `planning`, `exploration`."""
