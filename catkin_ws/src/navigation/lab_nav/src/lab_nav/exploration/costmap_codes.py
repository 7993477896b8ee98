"""OccupancyGrid values mapped back to costmap_2d's cell codes, as explore_lite's costmap client maps /map.

0 -> 0 (free), 99 -> 253 (inscribed), 100 -> 254 (lethal), -1 -> 255 (no information), and 1-98 linearly onto
1-252 by 1 + 251 * (v - 1) / 97 in integer arithmetic. Values outside -1..100 (which no map server sends) go
through the same formula on their unsigned byte and wrap, as in the original's lookup table.
"""

import numpy as np

from lab_nav.costmap.values import FREE, INSCRIBED, LETHAL, NO_INFORMATION


def _translation_table():
    values = np.arange(256, dtype=np.int64)
    table = ((1 + (251 * (values - 1)) // 97) & 0xFF).astype(np.uint8)
    table[0] = FREE
    table[99] = INSCRIBED
    table[100] = LETHAL
    table[255] = NO_INFORMATION   # -1 as an unsigned byte
    return table


TRANSLATION_TABLE = _translation_table()


def costmap_codes(occupancy):
    """uint8 costmap codes of an array of OccupancyGrid values (int8 or ints in -128..127), same shape."""
    return TRANSLATION_TABLE[np.asarray(occupancy).astype(np.int8).view(np.uint8)]


def apply_update(codes, x, y, width, height, values):
    """Write a map_msgs/OccupancyGridUpdate (origin cell x, y; width x height values, row-major) into `codes`
    (uint8, (rows, cols)) in place, as explore_lite's costmap client does; returns the warning or error it would
    log, or None. Negative coordinates, and data that do not hold width x height values, are refused. Parts
    beyond the grid are cut off, and the values are taken in order for the cells that remain (so a clipped
    update's rows shift, as in the original)."""
    if x < 0 or y < 0:
        return "negative coordinates, invalid update. x: {}, y: {}".format(x, y)
    rows, cols = codes.shape
    x_end, y_end = x + width, y + height
    warning = None
    if x_end > cols or x > cols or y_end > rows or y > rows:
        warning = ("received update doesn't fully fit into existing map, only part will be copied. received: "
                   "[{}, {}], [{}, {}] map is: [0, {}], [0, {}]".format(x, x_end, y, y_end, cols, rows))
    if len(values) != width * height:
        return "invalid update: {} x {} cells but {} values".format(width, height, len(values))
    kept_cols, kept_rows = max(0, min(x_end, cols) - x), max(0, min(y_end, rows) - y)
    taken = costmap_codes(np.asarray(values[:kept_cols * kept_rows], dtype=np.int64))
    codes[y:y + kept_rows, x:x + kept_cols] = taken.reshape(kept_rows, kept_cols)
    return warning
