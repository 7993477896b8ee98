"""The two files map_saver writes for a map, byte for byte as the original writes them.

NAME.pgm: binary PGM, header "P5\\n# CREATOR: map_saver.cpp <resolution %.3f> m/pix\\n<W> <H>\\n255\\n", then one
byte per cell with the map's last row first (the image is the map seen from above, y up): 254 for a free cell
(0 <= v <= free threshold, default 25), 0 for an occupied one (v >= occupied threshold, default 65), 205 for
everything else, unknown (-1) included.

NAME.yaml: image (the -f name plus .pgm, as typed), resolution and origin with C's %f (six decimals), the yaw
taken from the origin's quaternion, negate 0 and the thresholds 0.65 / 0.196 (constants: they do not follow
--occ/--free), no mode key, and an empty line at the end.
"""

import math

import numpy as np

DEFAULT_OCCUPIED_THRESHOLD = 65
DEFAULT_FREE_THRESHOLD = 25
PGM_FREE = 254
PGM_OCCUPIED = 0
PGM_UNKNOWN = 205

YAML_TEMPLATE = ("image: {image}\nresolution: {resolution:f}\norigin: [{x:f}, {y:f}, {yaw:f}]\nnegate: 0\n"
                 "occupied_thresh: 0.65\nfree_thresh: 0.196\n\n")


def pgm_pixels(cells, occupied_threshold=DEFAULT_OCCUPIED_THRESHOLD, free_threshold=DEFAULT_FREE_THRESHOLD):
    """uint8 image (height, width), top row first, of int cells (height, width) with row 0 at the origin."""
    cells = np.asarray(cells)
    pixels = np.full(cells.shape, PGM_UNKNOWN, np.uint8)
    pixels[cells >= occupied_threshold] = PGM_OCCUPIED
    pixels[(cells >= 0) & (cells <= free_threshold)] = PGM_FREE
    return pixels[::-1]


def pgm_bytes(cells, resolution, occupied_threshold=DEFAULT_OCCUPIED_THRESHOLD,
              free_threshold=DEFAULT_FREE_THRESHOLD):
    """The whole NAME.pgm file for `cells` (height, width) at `resolution` m/cell."""
    height, width = np.asarray(cells).shape
    header = "P5\n# CREATOR: map_saver.cpp {:.3f} m/pix\n{} {}\n255\n".format(resolution, width, height)
    return header.encode("ascii") + pgm_pixels(cells, occupied_threshold, free_threshold).tobytes()


def quaternion_yaw(x, y, z, w):
    """Yaw in rad of a quaternion, computed as tf2's Matrix3x3::getEulerYPR computes it (so a yaw that comes out
    as -0.0 prints as -0.000000, as the original's would). The all-zero quaternion of an unset Pose gives 0: the
    original divides by zero there and writes -nan, which no map_server can read back."""
    norm2 = x * x + y * y + z * z + w * w
    if norm2 == 0:
        return 0.0
    s = 2.0 / norm2
    ys, zs = y * s, z * s
    m00 = 1.0 - (y * ys + z * zs)
    m10 = x * ys + w * zs
    m20 = x * zs - w * ys
    if abs(m20) >= 1:
        return 0.0
    cos_pitch = math.cos(-math.asin(m20))
    return math.atan2(m10 / cos_pitch, m00 / cos_pitch)


def yaml_text(image, resolution, origin_x, origin_y, origin_yaw):
    """The whole NAME.yaml file; `image` is written as given (map_saver's -f argument plus .pgm)."""
    return YAML_TEMPLATE.format(image=image, resolution=resolution, x=origin_x, y=origin_y, yaw=origin_yaw)
