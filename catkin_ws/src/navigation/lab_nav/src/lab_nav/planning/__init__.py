"""move_base's planners and state machine: navfn-style Dijkstra, the DWA local planner, recoveries, goals."""
