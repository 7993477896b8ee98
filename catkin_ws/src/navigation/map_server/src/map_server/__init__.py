"""map_server's two nodes: `server_node` (map_server) and `saver_node` (map_saver), thin ROS layers over
lab_nav.maps; `command_line` holds their argument rules, `messages` the grid <-> OccupancyGrid conversion."""
