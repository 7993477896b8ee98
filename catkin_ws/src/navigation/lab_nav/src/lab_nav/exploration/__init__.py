"""explore_lite's frontier exploration, plain Python: costmap codes from /map values, the frontier search, goal
choice with a blacklist."""
