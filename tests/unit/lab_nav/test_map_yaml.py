"""Map YAML files: every key, mode and error as map_server reads them."""
import textwrap

import pytest

from lab_nav.maps.errors import MapFileError
from lab_nav.maps.map_yaml import parse_map_yaml, read_map_yaml

GOOD = """\
image: room.pgm
resolution: 0.05
origin: [-10.0, -7.5, 0.5]
negate: 0
occupied_thresh: 0.65
free_thresh: 0.196
"""


def without(key):
    return "".join(line + "\n" for line in GOOD.splitlines() if not line.startswith(key + ":"))


def test_every_key_is_read_and_a_relative_image_is_resolved_against_the_yamls_folder():
    description = parse_map_yaml(GOOD + "mode: scale\n", "/maps/lab/room.yaml")
    assert description.image == "/maps/lab/room.pgm"
    assert (description.resolution, description.origin, description.negate) == (0.05, (-10.0, -7.5, 0.5), 0)
    assert (description.occupied_thresh, description.free_thresh, description.mode) == (0.65, 0.196, "scale")


def test_the_mode_defaults_to_trinary_and_an_absolute_image_path_is_kept():
    description = parse_map_yaml(GOOD.replace("room.pgm", "/srv/room.png"), "room.yaml")
    assert (description.image, description.mode) == ("/srv/room.png", "trinary")


def test_a_yaml_without_a_folder_keeps_the_image_relative_to_the_working_directory():
    assert parse_map_yaml(GOOD, "room.yaml").image == "room.pgm"


def test_integers_and_exponents_are_numbers_as_yaml_cpp_reads_them():
    text = GOOD.replace("0.05", "5e-2").replace("[-10.0, -7.5, 0.5]", "[-10, 0, 0, 99]")
    description = parse_map_yaml(text, "room.yaml")
    assert (description.resolution, description.origin) == (0.05, (-10.0, 0.0, 0.0))


@pytest.mark.parametrize("key, article", [("resolution", "a"), ("negate", "a"), ("occupied_thresh", "an"),
                                          ("free_thresh", "a"), ("origin", "an"), ("image", "an")])
def test_a_missing_key_gets_map_servers_sentence(key, article):
    with pytest.raises(MapFileError) as error:
        parse_map_yaml(without(key), "room.yaml")
    assert str(error.value) == "The map does not contain {} {} tag or it is invalid.".format(article, key)


@pytest.mark.parametrize("old, new, key", [
    ("resolution: 0.05", "resolution: fine", "resolution"),
    ("resolution: 0.05", "resolution: 0", "resolution"),
    ("negate: 0", "negate: 0.5", "negate"),
    ("negate: 0", "negate: true", "negate"),
    ("occupied_thresh: 0.65", "occupied_thresh: [1]", "occupied_thresh"),
    ("origin: [-10.0, -7.5, 0.5]", "origin: [1, 2]", "origin"),
    ("origin: [-10.0, -7.5, 0.5]", "origin: [1, x, 2]", "origin"),
    ("image: room.pgm", "image:", "image"),
])
def test_an_invalid_value_is_reported_like_a_missing_one(old, new, key):
    with pytest.raises(MapFileError, match="contain an? {} tag or it is invalid".format(key)):
        parse_map_yaml(GOOD.replace(old, new), "room.yaml")


def test_the_first_bad_key_in_map_servers_order_is_the_one_reported():
    with pytest.raises(MapFileError, match="negate"):
        parse_map_yaml("image: ''\norigin: 3\n" + without("negate"), "room.yaml")


def test_an_empty_image_and_an_unknown_mode_have_their_own_messages():
    with pytest.raises(MapFileError, match=r"^The image tag cannot be an empty string\.$"):
        parse_map_yaml(GOOD.replace("room.pgm", "''"), "room.yaml")
    with pytest.raises(MapFileError, match=r'^Invalid mode tag "grey"\.$'):
        parse_map_yaml(GOOD + "mode: grey\n", "room.yaml")


def test_a_file_that_cannot_be_opened_or_parsed_is_named(tmp_path):
    with pytest.raises(MapFileError, match=r"^Map_server could not open /no/such/map\.yaml\.$"):
        read_map_yaml("/no/such/map.yaml")
    broken = tmp_path / "broken.yaml"
    broken.write_text(textwrap.dedent("""\
        image: room.pgm
        origin: [1, 2
        """))
    with pytest.raises(MapFileError, match=r"broken\.yaml is not valid YAML: .*line"):
        read_map_yaml(str(broken))


def test_an_empty_file_lacks_the_first_key():
    with pytest.raises(MapFileError, match="resolution"):
        parse_map_yaml("", "empty.yaml")
