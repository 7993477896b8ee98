"""Colours: Gazebo's named materials, SDF/URDF rgba text, world-file colour names and hex, defaults, messages."""

import math

import pytest

from tb3_sim.core.materials import (
    DEFAULT_MODEL_RGB,
    DEFAULT_WALL_RGB,
    FLOOR_RGB,
    GAZEBO_MATERIALS,
    SKY_RGB,
    ColourError,
    UnknownMaterialError,
    colour_from_name_or_hex,
    material_rgb,
    rgba_text_to_rgb,
)


@pytest.mark.parametrize("name, rgb", [
    ("Gazebo/Red", (255, 0, 0)),
    ("Gazebo/Green", (0, 255, 0)),
    ("Gazebo/Blue", (0, 0, 255)),
    ("Gazebo/Yellow", (255, 255, 0)),
    ("Gazebo/Purple", (255, 0, 255)),
    ("Gazebo/Turquoise", (0, 255, 255)),
    ("Gazebo/White", (255, 255, 255)),
    ("Gazebo/Black", (0, 0, 0)),
    ("Gazebo/Grey", (178, 178, 178)),  # diffuse 0.7
    ("Gazebo/DarkGrey", (45, 45, 45)),  # 0.175
    ("Gazebo/FlatBlack", (26, 26, 26)),  # 0.1
    ("Gazebo/Orange", (255, 130, 12)),  # 1 0.5088 0.0468
    ("Gazebo/RedBright", (222, 66, 18)),  # 0.87 0.26 0.07
    ("Gazebo/SkyBlue", (0, 0, 255)),  # diffuse 0 0 1 (its ambient is 0.13 0.44 0.70)
    ("Gazebo/ZincYellow", (248, 243, 53)),  # 0.9725 0.9529 0.2078
    ("Gazebo/Gold", (204, 165, 31)),  # diffuse 0.8 0.64869 0.120759
])
def test_named_materials_use_gazebos_diffuse_colour(name, rgb):
    assert material_rgb(name) == rgb


def test_every_material_is_whole_channels_in_range():
    for name in GAZEBO_MATERIALS:
        rgb = material_rgb(name)
        assert len(rgb) == 3 and all(isinstance(c, int) and 0 <= c <= 255 for c in rgb)


def test_unknown_material_names_it_and_suggests_known_ones():
    with pytest.raises(UnknownMaterialError) as error:
        material_rgb("Gazebo/Redd")
    assert isinstance(error.value, ValueError)
    message = str(error.value)
    assert "'Gazebo/Redd'" in message and "did you mean Gazebo/Red" in message and "Gazebo/Blue" in message


def test_material_names_are_exact():
    with pytest.raises(UnknownMaterialError):
        material_rgb("gazebo/red")


@pytest.mark.parametrize("text, rgb", [
    ("1 0 0 1", (255, 0, 0)),
    ("0 1 0", (0, 255, 0)),
    ("  0.5\t0.5 0.5  0.3 ", (128, 128, 128)),
    ("0.7 0.7 0.7 1.0", (178, 178, 178)),
    ("1e-3 0 1", (0, 0, 255)),
])
def test_rgba_text(text, rgb):
    assert rgba_text_to_rgb(text) == rgb


@pytest.mark.parametrize("text, detail", [
    ("1 0", "got '1 0'"),
    ("1 0 0 1 1", "got '1 0 0 1 1'"),
    ("", "got ''"),
    ("red green blue", "got 'red green blue'"),
    ("1.5 0 0", "1.5 out of range"),
    ("0 -0.1 0 1", "-0.1 out of range"),
    ("0 0 0 2", "2 out of range"),
    ("nan 0 0", "nan out of range"),
    ("inf 0 0", "inf out of range"),
    (None, "got None"),
])
def test_bad_rgba_text_says_what_is_expected(text, detail):
    with pytest.raises(ColourError) as error:
        rgba_text_to_rgb(text)
    assert "expected 3 or 4 numbers 'r g b [a]', each in [0, 1]" in str(error.value)
    assert detail in str(error.value)


@pytest.mark.parametrize("text, rgb", [
    ("red", (255, 0, 0)),
    (" Red ", (255, 0, 0)),
    ("purple", (255, 0, 255)),  # Gazebo/Purple
    ("grey", (178, 178, 178)),
    ("gray", (178, 178, 178)),
    ("light grey", (211, 211, 211)),
    ("light_gray", (211, 211, 211)),
    ("Dark-Grey", (45, 45, 45)),
    ("#ff8800", (255, 136, 0)),
    ("#FF8800", (255, 136, 0)),
    ("#f80", (255, 136, 0)),
    ("Gazebo/Blue", (0, 0, 255)),
])
def test_world_file_colours(text, rgb):
    assert colour_from_name_or_hex(text) == rgb


@pytest.mark.parametrize("text, detail", [
    ("reddish", "unknown colour 'reddish'; use one of"),
    ("#ff88", "expected a hex colour '#rrggbb' or '#rgb', got '#ff88'"),
    ("#gg0000", "got '#gg0000'"),
    ("Gazebo/Rouge", "unknown Gazebo material 'Gazebo/Rouge'"),
    (42, "got 42"),
])
def test_bad_world_file_colours(text, detail):
    with pytest.raises(ColourError) as error:
        colour_from_name_or_hex(text)
    assert detail in str(error.value)


def test_unknown_colour_lists_the_names():
    with pytest.raises(ColourError) as error:
        colour_from_name_or_hex("mauve")
    assert all(name in str(error.value) for name in ("red", "lightgrey", "turquoise", "'#rrggbb'", "Gazebo/Red"))


def test_gazebo_defaults():
    assert DEFAULT_MODEL_RGB == DEFAULT_WALL_RGB == material_rgb("Gazebo/Grey")
    assert SKY_RGB == (178, 178, 178)  # SDF <scene><background> .7 .7 .7
    # Gazebo/Grey ground plane: ambient 0.3 x scene ambient 0.4 + diffuse 0.7 x sun 0.8 x cos(sun from vertical).
    sun_cos = 1.0 / math.sqrt(0.5 ** 2 + 0.5 ** 2 + 1.0)
    assert FLOOR_RGB == (round(255 * (0.3 * 0.4 + 0.7 * 0.8 * sun_cos)),) * 3 == (147, 147, 147)
