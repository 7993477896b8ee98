"""Image pixels to occupancy cells, exactly as map_server's image loader converts them.

Per pixel: the mean of its channels (in trinary mode an alpha channel is averaged in too; in scale and raw mode it
is left out), replaced by 255 - mean when `negate` is set, then p = (255 - mean) / 255, the probability that the
cell is occupied:
- trinary: p > occupied_thresh -> 100, p < free_thresh -> 0, otherwise -1. With the usual 0.65 / 0.196,
  pixel <= 89 -> 100, pixel >= 206 -> 0, 90-205 -> -1, so map_saver's 0 / 205 / 254 come back as 100 / -1 / 0.
- scale: as trinary, but in-between values become 1 + 98 * (p - free) / (occ - free), truncated (1-99); a pixel
  whose alpha is 0 stays -1. "Alpha" is the last channel's byte, as the original reads it, so for an RGB image
  without alpha it is the blue byte (a quirk kept on purpose); a one-channel image has none.
- raw: the (negated) mean itself, truncated to a byte and stored as int8, so 128-255 wrap to -128..-1.
The image's top row becomes the map's last row (map row 0 is the image's bottom row).
"""

import numpy as np

from lab_nav.maps.grid_map import FREE, OCCUPIED, UNKNOWN

SCALE_SPAN = 98   # in-between cells of scale mode run from 1 to 1 + 98 = 99


def _means(pixels, include_alpha, has_alpha):
    """Mean channel value per pixel (float), over the colour channels or all channels."""
    channels = pixels.shape[2]
    averaged = channels if include_alpha or not has_alpha else channels - 1
    return pixels[:, :, :averaged].sum(axis=2, dtype=np.int64) / float(averaged)


def _lightness(pixels, include_alpha, has_alpha, negate):
    means = _means(pixels, include_alpha, has_alpha)
    return 255.0 - means if negate else means


def _occupancy(lightness):
    """p = (255 - mean) / 255, computed in this order so that threshold ties fall as in the original."""
    return (255.0 - lightness) / 255.0


def _thresholded(occupancy, occupied_thresh, free_thresh, between):
    return np.where(occupancy > occupied_thresh, OCCUPIED, np.where(occupancy < free_thresh, FREE, between))


def _trinary(pixels, has_alpha, negate, occupied_thresh, free_thresh):
    occupancy = _occupancy(_lightness(pixels, True, has_alpha, negate))
    return _thresholded(occupancy, occupied_thresh, free_thresh, UNKNOWN)


def _scale(pixels, has_alpha, negate, occupied_thresh, free_thresh):
    occupancy = _occupancy(_lightness(pixels, False, has_alpha, negate))
    with np.errstate(divide="ignore", invalid="ignore"):
        ratio = np.nan_to_num((occupancy - free_thresh) / (occupied_thresh - free_thresh))
    scaled = np.trunc(1 + SCALE_SPAN * ratio)
    transparent = np.zeros(occupancy.shape, bool) if pixels.shape[2] == 1 else pixels[:, :, -1] == 0
    return _thresholded(occupancy, occupied_thresh, free_thresh, np.where(transparent, UNKNOWN, scaled))


def _raw(pixels, has_alpha, negate, occupied_thresh, free_thresh):
    return np.trunc(_lightness(pixels, False, has_alpha, negate)).astype(np.uint8).view(np.int8)


CONVERTERS = {"trinary": _trinary, "scale": _scale, "raw": _raw}


def pixels_to_cells(pixels, has_alpha, mode, negate, occupied_thresh, free_thresh):
    """int8 cells (height, width), row 0 at the bottom, from `pixels` (uint8, (height, width, channels), top row
    first); `has_alpha` says the last channel is alpha. `mode` is one of CONVERTERS."""
    cells = CONVERTERS[mode](np.asarray(pixels), has_alpha, bool(negate), occupied_thresh, free_thresh)
    return np.ascontiguousarray(np.asarray(cells).astype(np.int16).astype(np.int8)[::-1])
