"""Map images read into pixel arrays, for whatever format Pillow reads (PGM, PNG, BMP, JPEG, ...), as map_server
reads any format SDL_image does.

Pixels come out as uint8 (height, width, channels), top row first: one channel for greyscale, three for RGB, four
for RGBA. Greyscale with alpha is read as RGBA, as SDL_image does. Palette images are read by their colours (the
original would use the palette index), and 16-bit greyscale is scaled to 8 bits.
"""

import numpy as np
from PIL import Image, UnidentifiedImageError

from lab_nav.maps.errors import MapFileError

GREY_8_BIT_MODES = ("L",)
COLOUR_MODES = {"RGB": False, "RGBA": True}   # mode: has alpha
CONVERTED_MODES = {"1": "L", "LA": "RGBA", "PA": "RGBA", "CMYK": "RGB", "YCbCr": "RGB", "LAB": "RGB", "HSV": "RGB"}
SIXTEEN_BIT_MODES = ("I;16", "I;16B", "I;16L", "I")


def _pixels(image):
    """(pixels, has_alpha) of a Pillow image in any mode."""
    mode = image.mode
    if mode == "P":
        mode = "RGBA" if "transparency" in image.info else "RGB"
        image = image.convert(mode)
    elif mode in CONVERTED_MODES:
        mode = CONVERTED_MODES[mode]
        image = image.convert(mode)
    if mode in SIXTEEN_BIT_MODES:
        wide = np.asarray(image, dtype=np.int64)
        return np.clip(wide >> 8, 0, 255).astype(np.uint8)[:, :, None], False
    if mode in GREY_8_BIT_MODES:
        return np.asarray(image, dtype=np.uint8)[:, :, None], False
    if mode in COLOUR_MODES:
        return np.asarray(image, dtype=np.uint8), COLOUR_MODES[mode]
    raise ValueError("unsupported pixel format {}".format(image.mode))


def read_image(path):
    """(pixels, has_alpha) of the image file `path`; MapFileError 'failed to open image file "PATH": REASON'."""
    try:
        with Image.open(path) as image:
            image.load()
            return _pixels(image)
    except (OSError, ValueError, UnidentifiedImageError, Image.DecompressionBombError) as error:
        reason = error.strerror if isinstance(error, OSError) and error.strerror else str(error)
        raise MapFileError('failed to open image file "{}": {}'.format(path, reason)) from None
