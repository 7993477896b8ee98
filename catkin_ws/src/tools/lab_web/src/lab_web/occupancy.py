"""nav_msgs/OccupancyGrid as the page draws it: one PNG, a pixel per cell, in RViz's "map" colour scheme.
No ROS import (the panel passes the message's fields); OpenCV encodes.

RViz's map palette: a value v in 0..100 is grey 255 - 255 * v / 100 (0 free: white, 100 occupied: black);
-1 (no information) is RViz's (0x70, 0x89, 0x86) grey; other values (101..127, -128..-2) are drawn as RViz's
"illegal" green and red-to-yellow ramp would show them, here one magenta so a bad grid stands out.
"""
import base64

import cv2
import numpy as np

UNKNOWN_RGB = (0x70, 0x89, 0x86)
ILLEGAL_RGB = (255, 0, 255)
MAX_CELLS = 4096 * 4096
"""A bigger grid is not drawn (64 MB of cells): the page says so instead."""


def _palette():
    palette = np.empty((256, 3), dtype=np.uint8)
    palette[:] = ILLEGAL_RGB
    for value in range(101):
        grey = 255 - (255 * value) // 100
        palette[value] = (grey, grey, grey)
    palette[255] = UNKNOWN_RGB     # int8 -1 read as uint8
    return palette


PALETTE = _palette()


def grid_png(data, width, height):
    """Base64 PNG (RGB) of an occupancy grid's row-major int8 `data` (bytes or a sequence), row 0 first as in
    the message (the page flips it: row 0 is the grid's lowest y). Raises ValueError for a size that does not
    add up or is too big."""
    if width <= 0 or height <= 0 or width * height > MAX_CELLS:
        raise ValueError("a map of {} x {} cells is not drawn (at most {} cells)".format(width, height, MAX_CELLS))
    cells = np.frombuffer(data, dtype=np.uint8) if isinstance(data, (bytes, bytearray)) else \
        np.asarray(data, dtype=np.int8).view(np.uint8)
    if cells.size != width * height:
        raise ValueError("the map has {} cells, its info says {} x {}".format(cells.size, width, height))
    rgb = PALETTE[cells.reshape(height, width)]
    ok, encoded = cv2.imencode(".png", cv2.cvtColor(rgb, cv2.COLOR_RGB2BGR), [cv2.IMWRITE_PNG_COMPRESSION, 1])
    if not ok:
        raise ValueError("the map could not be encoded")
    return base64.b64encode(encoded.tobytes()).decode()
