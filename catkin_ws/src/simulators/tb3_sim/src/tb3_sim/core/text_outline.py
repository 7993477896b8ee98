"""Glyph outlines of a primitives.Text as polygon rings in the world frame, so that renderers without a font system
(the camera's floor texture, a QImage painted without a QGuiApplication, which Qt cannot lay text out without)
draw the same letters. The font is DejaVu Sans (matplotlib's bundled default, sans-serif like the course floors),
bold when asked; fill the rings with the even-odd rule (letter holes are rings). matplotlib is imported on first
use (about 0.5 s), so only worlds with text pay for it.
"""

import math
from functools import lru_cache

import numpy as np

FONT_FAMILY = "DejaVu Sans"
# Cap height is measured on this letter.
_CAP_LETTER = "H"


@lru_cache(maxsize=None)
def _unit_rings(text, bold):
    """Rings of `text` with a cap height of 1, glyph box centred on (0, 0), reading along +x."""
    from matplotlib.font_manager import FontProperties
    from matplotlib.textpath import TextPath

    font = FontProperties(family=FONT_FAMILY, weight="bold" if bold else "normal")
    cap = TextPath((0, 0), _CAP_LETTER, size=1.0, prop=font).get_extents().height
    path = TextPath((0, 0), text, size=1.0 / cap, prop=font)
    box = path.get_extents()
    centre = np.array(((box.x0 + box.x1) / 2.0, (box.y0 + box.y1) / 2.0))
    return tuple(np.asarray(ring, dtype=float) - centre for ring in path.to_polygons() if len(ring) >= 3)


def text_rings(text):
    """Rings ((n, 2) arrays, metres, world frame) of the primitives.Text `text`."""
    angle = math.radians(text.angle_deg)
    rotation = np.array(((math.cos(angle), math.sin(angle)), (-math.sin(angle), math.cos(angle))))
    return [ring * text.height @ rotation + text.position for ring in _unit_rings(text.text, text.bold)]
