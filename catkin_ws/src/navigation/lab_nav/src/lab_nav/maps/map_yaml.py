"""map_server's map description file (NAME.yaml), read and checked as map_server reads it.

Keys (all required but `mode`): image (a path; relative paths are resolved against the YAML file's directory),
resolution (m/cell), origin ([x, y, yaw] in m and rad: the pose of the image's lower-left pixel; entries past the
third are ignored), negate (integer 0/1), occupied_thresh and free_thresh (probabilities), mode (trinary, the
default, scale or raw). Keys are checked in map_server's order and the first bad one is reported with
map_server's own sentence, e.g. "The map does not contain a resolution tag or it is invalid.". Unknown keys are
ignored, as map_server ignores them. Kept stricter than map_server on purpose: a resolution that is not a
positive finite number is reported as invalid (map_server would publish a map no tool can draw).
"""

import math
import os
from dataclasses import dataclass

import yaml

from lab_nav.maps.errors import MapFileError

DEFAULT_MODE = "trinary"
MODES = ("trinary", "scale", "raw")


@dataclass(frozen=True)
class MapDescription:
    """What a map YAML says; `image` is already resolved against the YAML's directory."""

    image: str
    resolution: float
    origin: tuple
    negate: int
    occupied_thresh: float
    free_thresh: float
    mode: str = DEFAULT_MODE


def _missing(key):
    article = "an" if key[0] in "aeiou" else "a"
    return MapFileError("The map does not contain {} {} tag or it is invalid.".format(article, key))


def _number(value):
    """A YAML scalar as a float the way yaml-cpp's as<double> reads it (1, 0.5, 5e-2 and '0.5' all are), or None."""
    if isinstance(value, bool) or value is None or isinstance(value, (list, dict)):
        return None
    try:
        return float(value)
    except (TypeError, ValueError):
        return None


def _float(doc, key):
    value = _number(doc.get(key))
    if value is None:
        raise _missing(key)
    return value


def _int(doc, key):
    value = doc.get(key)
    if isinstance(value, bool) or not isinstance(value, int):
        raise _missing(key)
    return value


def _scalar_text(value):
    """A YAML scalar as yaml-cpp's as<string> gives it (its source text for numbers and booleans)."""
    if isinstance(value, bool):
        return "true" if value else "false"
    return str(value)


def _mode(doc):
    """map_server falls back to trinary when `mode` is absent or not a scalar, and refuses an unknown name."""
    value = doc.get("mode")
    if value is None or isinstance(value, (list, dict)):
        return DEFAULT_MODE
    mode = _scalar_text(value)
    if mode not in MODES:
        raise MapFileError('Invalid mode tag "{}".'.format(mode))
    return mode


def _origin(doc):
    value = doc.get("origin")
    if not isinstance(value, list) or len(value) < 3:
        raise _missing("origin")
    numbers = [_number(item) for item in value[:3]]
    if None in numbers:
        raise _missing("origin")
    return tuple(numbers)


def _image(doc, yaml_path):
    value = doc.get("image")
    if value is None or isinstance(value, (list, dict)):
        raise _missing("image")
    image = _scalar_text(value)
    if not image:
        raise MapFileError("The image tag cannot be an empty string.")
    return image if os.path.isabs(image) else os.path.join(os.path.dirname(yaml_path), image)


def parse_map_yaml(text, yaml_path):
    """The MapDescription in `text` (the contents of `yaml_path`, which relative image paths are resolved
    against); raises MapFileError naming the first missing or invalid key."""
    try:
        doc = yaml.safe_load(text)
    except yaml.YAMLError as error:
        raise MapFileError("map_server exception: {} is not valid YAML: {}".format(
            yaml_path, " ".join(str(error).split()))) from None
    if not isinstance(doc, dict):
        doc = {}
    resolution = _float(doc, "resolution")
    if not (math.isfinite(resolution) and resolution > 0):
        raise _missing("resolution")
    negate = _int(doc, "negate")
    occupied_thresh = _float(doc, "occupied_thresh")
    free_thresh = _float(doc, "free_thresh")
    mode = _mode(doc)
    origin = _origin(doc)
    image = _image(doc, yaml_path)
    return MapDescription(image=image, resolution=resolution, origin=origin, negate=negate,
                          occupied_thresh=occupied_thresh, free_thresh=free_thresh, mode=mode)


def read_map_yaml(yaml_path):
    """The MapDescription in the file `yaml_path`; MapFileError "Map_server could not open PATH." when it cannot
    be read, or the first bad key's sentence."""
    try:
        with open(yaml_path, encoding="utf-8") as yaml_file:
            text = yaml_file.read()
    except (OSError, UnicodeDecodeError):
        raise MapFileError("Map_server could not open {}.".format(yaml_path)) from None
    return parse_map_yaml(text, yaml_path)
