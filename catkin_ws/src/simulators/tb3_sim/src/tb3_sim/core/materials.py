"""Colours for the camera: Gazebo's named materials, SDF/URDF colour text, world-file colour names, and defaults.

Gazebo classic's named materials come from `media/materials/scripts/gazebo.material` (gazebo-classic), used in
SDF as `<material><script><name>Gazebo/Red</name></script></material>` and in URDF as
`<gazebo reference="..."><material>Gazebo/Red</material></gazebo>`. Each has an ambient and a diffuse colour
(floats 0..1); the camera draws one colour per object, the diffuse one: the colour a surface shows under white
light. For Gazebo's plain colours ambient equals diffuse; GAZEBO_MATERIALS keeps both. Textured materials
(Gazebo/Wood, Gazebo/Residential) keep their untextured colours: the texture images are not modelled.

Every colour here is an (r, g, b) tuple of ints 0..255. Errors are ColourError (a ValueError) with a message that
names the bad input and what is allowed.
"""
import difflib
import math
from typing import NamedTuple

_MAX_CHANNEL = 255
_HEX_DIGITS_LONG, _HEX_DIGITS_SHORT = 6, 3
_SUGGESTIONS = 3


class ColourError(ValueError):
    """A colour or material text the lab cannot use."""


class UnknownMaterialError(ColourError):
    """A Gazebo material name that is not in GAZEBO_MATERIALS."""


class GazeboMaterial(NamedTuple):
    """A material's ambient and diffuse colours as gazebo.material gives them, floats 0..1 (r, g, b)."""

    ambient: tuple
    diffuse: tuple


# From gazebo-classic media/materials/scripts/gazebo.material (the `ambient` and `diffuse` lines of each
# material's pass; Gazebo/White splits them over two passes). Gazebo/DarkYellow and Gazebo/Indigo exist in newer
# Gazebo releases but their values could not be confirmed, so they are not here.
GAZEBO_MATERIALS = {
    "Gazebo/Grey": GazeboMaterial((0.3, 0.3, 0.3), (0.7, 0.7, 0.7)),
    "Gazebo/DarkGrey": GazeboMaterial((0.175, 0.175, 0.175), (0.175, 0.175, 0.175)),
    "Gazebo/White": GazeboMaterial((1.0, 1.0, 1.0), (1.0, 1.0, 1.0)),
    "Gazebo/FlatBlack": GazeboMaterial((0.1, 0.1, 0.1), (0.1, 0.1, 0.1)),
    "Gazebo/Black": GazeboMaterial((0.0, 0.0, 0.0), (0.0, 0.0, 0.0)),
    "Gazebo/Red": GazeboMaterial((1.0, 0.0, 0.0), (1.0, 0.0, 0.0)),
    "Gazebo/RedBright": GazeboMaterial((0.87, 0.26, 0.07), (0.87, 0.26, 0.07)),
    "Gazebo/Green": GazeboMaterial((0.0, 1.0, 0.0), (0.0, 1.0, 0.0)),
    "Gazebo/Blue": GazeboMaterial((0.0, 0.0, 1.0), (0.0, 0.0, 1.0)),
    "Gazebo/SkyBlue": GazeboMaterial((0.13, 0.44, 0.70), (0.0, 0.0, 1.0)),
    "Gazebo/Yellow": GazeboMaterial((1.0, 1.0, 0.0), (1.0, 1.0, 0.0)),
    "Gazebo/ZincYellow": GazeboMaterial((0.9725, 0.9529, 0.2078), (0.9725, 0.9529, 0.2078)),
    "Gazebo/Purple": GazeboMaterial((1.0, 0.0, 1.0), (1.0, 0.0, 1.0)),
    "Gazebo/Turquoise": GazeboMaterial((0.0, 1.0, 1.0), (0.0, 1.0, 1.0)),
    "Gazebo/Orange": GazeboMaterial((1.0, 0.5088, 0.0468), (1.0, 0.5088, 0.0468)),
    "Gazebo/Gold": GazeboMaterial((0.4, 0.24869, 0.020759), (0.8, 0.64869, 0.120759)),
    "Gazebo/Wood": GazeboMaterial((1.0, 1.0, 1.0), (1.0, 1.0, 1.0)),
    "Gazebo/Residential": GazeboMaterial((0.1, 0.1, 0.1), (0.8, 0.8, 0.8)),
}

# Plain names for world files: Gazebo's material where one matches the name (so "purple" is Gazebo/Purple's
# magenta, as in a Gazebo world), else the CSS colour of that name.
_PLAIN_MATERIALS = {
    "red": "Gazebo/Red", "green": "Gazebo/Green", "blue": "Gazebo/Blue", "yellow": "Gazebo/Yellow",
    "orange": "Gazebo/Orange", "purple": "Gazebo/Purple", "magenta": "Gazebo/Purple", "turquoise": "Gazebo/Turquoise",
    "cyan": "Gazebo/Turquoise", "white": "Gazebo/White", "black": "Gazebo/Black", "grey": "Gazebo/Grey",
    "gray": "Gazebo/Grey", "darkgrey": "Gazebo/DarkGrey", "darkgray": "Gazebo/DarkGrey", "gold": "Gazebo/Gold",
    "skyblue": "Gazebo/SkyBlue",
}
_CSS_COLOURS = {"lightgrey": (211, 211, 211), "lightgray": (211, 211, 211), "brown": (165, 42, 42),
                "pink": (255, 192, 203)}


def rgb_from_unit(channels):
    """(r, g, b) 0..255 from channels in [0, 1] (as SDF, URDF and world files give them)."""
    return tuple(round(_MAX_CHANNEL * c) for c in channels)


def material_rgb(name):
    """The diffuse colour of Gazebo material `name` (exact, e.g. "Gazebo/Red") as (r, g, b) 0..255.

    Raises UnknownMaterialError naming `name` and suggesting known materials."""
    material = GAZEBO_MATERIALS.get(name)
    if material is None:
        known = sorted(GAZEBO_MATERIALS)
        close = difflib.get_close_matches(str(name), known, n=_SUGGESTIONS)
        hint = f"did you mean {' or '.join(close)}? " if close else ""
        raise UnknownMaterialError(f"unknown Gazebo material {name!r}; {hint}known: {', '.join(known)}")
    return rgb_from_unit(material.diffuse)


def rgba_text_to_rgb(text):
    """(r, g, b) 0..255 from SDF <ambient>/<diffuse> or URDF <color rgba="..."> text: 3 or 4 numbers in [0, 1]
    separated by spaces ("1 0 0 1"); alpha is checked and dropped."""
    expected = "expected 3 or 4 numbers 'r g b [a]', each in [0, 1]"
    parts = text.split() if isinstance(text, str) else []
    if len(parts) not in (3, 4):
        raise ColourError(f"{expected}, got {text!r}")
    try:
        channels = [float(part) for part in parts]
    except ValueError:
        raise ColourError(f"{expected}, got {text!r}") from None
    bad = [part for part, value in zip(parts, channels) if not (math.isfinite(value) and 0.0 <= value <= 1.0)]
    if bad:
        raise ColourError(f"{expected}, got {text!r} ({', '.join(bad)} out of range)")
    return rgb_from_unit(channels[:3])


def colour_from_name_or_hex(text):
    """(r, g, b) 0..255 from a world file's colour: a plain name ("red", "lightgrey"; case, spaces, '-' and '_'
    ignored), "#rrggbb" or "#rgb" hex, or a Gazebo material ("Gazebo/Red")."""
    if not isinstance(text, str):
        raise ColourError(f"expected a colour name, '#rrggbb' or a Gazebo material name, got {text!r}")
    stripped = text.strip()
    if stripped.startswith("Gazebo/"):
        return material_rgb(stripped)
    if stripped.startswith("#"):
        return _hex_rgb(stripped)
    key = "".join(stripped.lower().split()).replace("-", "").replace("_", "")
    if key in _PLAIN_MATERIALS:
        return material_rgb(_PLAIN_MATERIALS[key])
    if key in _CSS_COLOURS:
        return _CSS_COLOURS[key]
    names = sorted({*_PLAIN_MATERIALS, *_CSS_COLOURS})
    raise ColourError(f"unknown colour {text!r}; use one of {', '.join(names)}, '#rrggbb' or a Gazebo material "
                      f"such as Gazebo/Red")


def _hex_rgb(text):
    digits = text[1:]
    if len(digits) == _HEX_DIGITS_SHORT:
        digits = "".join(digit * 2 for digit in digits)
    try:
        if len(digits) != _HEX_DIGITS_LONG:
            raise ValueError
        return tuple(int(digits[i:i + 2], 16) for i in range(0, _HEX_DIGITS_LONG, 2))
    except ValueError:
        raise ColourError(f"expected a hex colour '#rrggbb' or '#rgb', got {text!r}") from None


# Gazebo's default look, with the source of each value.
# New shapes from Gazebo's model editor get Gazebo/Grey (gazebo-classic gui/model PartData: SetMaterial).
DEFAULT_MODEL_RGB = material_rgb("Gazebo/Grey")
# Walls saved by Gazebo's building editor use Gazebo/Grey.
DEFAULT_WALL_RGB = material_rgb("Gazebo/Grey")
# Another TurtleBot3 as a camera sees it: the dark grey plates of its body (Gazebo/DarkGrey, the colour the
# turtlebot3 gazebo.xacro gives base_link).
ROBOT_RGB = material_rgb("Gazebo/DarkGrey")
# SDF <scene><background> default ".7 .7 .7 1" (sdformat scene.sdf): a plain light grey, not a blue sky.
SKY_RGB = rgb_from_unit((0.7, 0.7, 0.7))

# The floor: gazebo_models' ground_plane (Gazebo/Grey) as Gazebo lights it from above. Fixed-function lighting
# gives ambient_colour * scene_ambient + diffuse_colour * sun_diffuse * cos(sun from vertical), with the SDF
# <scene><ambient> default 0.4 and gazebo_models' `sun` (diffuse 0.8, direction (-0.5, 0.5, -1.0)).
_SCENE_AMBIENT = 0.4
_SUN_DIFFUSE = 0.8
_SUN_DIRECTION = (-0.5, 0.5, -1.0)
_SUN_COS_FROM_VERTICAL = -_SUN_DIRECTION[2] / math.hypot(*_SUN_DIRECTION)
_GROUND = GAZEBO_MATERIALS["Gazebo/Grey"]
FLOOR_RGB = rgb_from_unit(a * _SCENE_AMBIENT + d * _SUN_DIFFUSE * _SUN_COS_FROM_VERTICAL
                    for a, d in zip(_GROUND.ambient, _GROUND.diffuse))

# A world's floor layer (its base colour, image and markings) as Gazebo lights the course floors: their material has
# ambient 0.5 and diffuse 1.0 under a sun of diffuse 0.8 coming from (-0.5, 0.1, -0.9), so a texel of colour c shows
# c * (0.5 * 0.4 + 1.0 * 0.8 * 0.9 / |(-0.5, 0.1, -0.9)|) = c * 0.896. A pink #ff00ff line shows as (228, 0, 228),
# yellow #ffff00 as (228, 228, 0): the hues stay, so ordinary HSV ranges still separate them.
_FLOOR_AMBIENT, _FLOOR_DIFFUSE, _COURSE_SUN_DIFFUSE = 0.5, 1.0, 0.8
_COURSE_SUN_DIRECTION = (-0.5, 0.1, -0.9)
FLOOR_LIGHT = (_FLOOR_AMBIENT * _SCENE_AMBIENT + _FLOOR_DIFFUSE * _COURSE_SUN_DIFFUSE
               * -_COURSE_SUN_DIRECTION[2] / math.sqrt(sum(c * c for c in _COURSE_SUN_DIRECTION)))
