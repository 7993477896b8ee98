#!/usr/bin/env python3
"""Course code reading the map (COM2009 Part 3 and the assignments): it waits for the latched /map and reads it
with numpy, row = y index, column = x index; free cells are 0, walls 100, unknown -1. Prints one JSON line: the
grid, its counts and its origin. Run by read_map_as_a_student()."""
import json

import numpy as np
import rospy
from nav_msgs.msg import OccupancyGrid


def main():
    rospy.init_node("map_reader")
    msg = rospy.wait_for_message("/map", OccupancyGrid, timeout=60)
    grid = np.array(msg.data).reshape((msg.info.height, msg.info.width))
    print(json.dumps({"grid": grid.tolist(), "free": int((grid == 0).sum()), "walls": int((grid == 100).sum()),
                      "unknown": int((grid == -1).sum()),
                      "origin": [msg.info.origin.position.x, msg.info.origin.position.y]}))


if __name__ == "__main__":
    main()
