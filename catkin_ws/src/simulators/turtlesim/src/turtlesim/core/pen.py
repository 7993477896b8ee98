"""A turtle's pen: colour and width, as the original's QPen."""
from typing import NamedTuple, Tuple

from turtlesim.core.constants import DEFAULT_PEN_COLOUR, DEFAULT_PEN_WIDTH


class Pen(NamedTuple):
    """Pen colour (r, g, b) 0..255 and width in pixels.

    width 0 means "never set": Qt 5's QPen(QColor) default width of 1 px applies, so a
    set_pen with width 0 still draws a thin line (quirk of the original kept).
    """

    colour: Tuple[int, int, int]
    width: int


DEFAULT_PEN = Pen(DEFAULT_PEN_COLOUR, DEFAULT_PEN_WIDTH)
