"""Background colour from the private ~background_r/g/b parameters, read like roscpp param<int>."""
import math

from turtlesim.core.constants import BACKGROUND_PARAMS, DEFAULT_BACKGROUND

CHANNEL_MASK = 0xFF
"""qRgb keeps the low 8 bits of each channel."""


def param_as_int(value, default):
    """roscpp NodeHandle::param<int>: int as is; double rounded; anything else -> default.

    A double d becomes floor(d) when fmod(d, 1) < 0.5, else ceil(d), so negative doubles
    always round down (roscpp quirk kept). bool and strings fall back to the default (XmlRpc
    types other than int/double). Non-finite doubles also fall back (undefined in C++).
    """
    if isinstance(value, bool):
        return default
    if isinstance(value, int):
        return value
    if isinstance(value, float) and math.isfinite(value):
        rounded = math.floor(value) if math.fmod(value, 1.0) < 0.5 else math.ceil(value)
        return int(rounded)
    return default


def read_background(read_param):
    """Return the background (r, g, b), each masked to 0..255.

    Args:
        read_param: callable(name) -> the parameter's value, or None when it is not set;
            called with 'background_r', 'background_g', 'background_b' (private names).
    """
    return tuple(param_as_int(read_param(name), default) & CHANNEL_MASK
                 for name, default in zip(BACKGROUND_PARAMS, DEFAULT_BACKGROUND))
