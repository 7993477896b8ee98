"""Rectangles of grid cells, the bounds a costmap layer reports so that an update recomputes only what changed.

A box is (r0, r1, c0, c1): rows r0..r1-1 and columns c0..c1-1, as numpy slices take them; None is the empty box.
costmap_2d's layers report the same (updateBounds), in metres; cells are what the numpy grids index.
"""
import numpy as np


def of_cells(rows, cols):
    """The smallest box holding the cells (rows, cols arrays); None when there are none."""
    rows, cols = np.asarray(rows), np.asarray(cols)
    if rows.size == 0:
        return None
    return int(rows.min()), int(rows.max()) + 1, int(cols.min()), int(cols.max()) + 1


def of_mask(mask, box):
    """The box of a boolean mask's True cells, the mask covering `box` of the grid; None when none is True."""
    rows, cols = np.nonzero(mask)
    if rows.size == 0:
        return None
    return of_cells(rows + box[0], cols + box[2])


def union(a, b):
    if a is None:
        return b
    if b is None:
        return a
    return min(a[0], b[0]), max(a[1], b[1]), min(a[2], b[2]), max(a[3], b[3])


def grown(box, margin, shape):
    """The box grown by `margin` cells on every side, clipped to a grid of `shape` (rows, cols)."""
    return (max(box[0] - margin, 0), min(box[1] + margin, shape[0]),
            max(box[2] - margin, 0), min(box[3] + margin, shape[1]))


def intersection(a, b):
    """The cells in both boxes; None when there are none."""
    if a is None or b is None:
        return None
    box = max(a[0], b[0]), min(a[1], b[1]), max(a[2], b[2]), min(a[3], b[3])
    return box if box[0] < box[1] and box[2] < box[3] else None


def slices(box, within=(0, None, 0, None)):
    """(row slice, column slice) of the box, for indexing a grid, or an array covering the box `within`."""
    return slice(box[0] - within[0], box[1] - within[0]), slice(box[2] - within[2], box[3] - within[2])
