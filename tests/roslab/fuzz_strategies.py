"""Hypothesis strategies for fuzzing ROS requests: the values a student's half-written client sends.

Each strategy stays inside what rospy can serialise for the field's type (a float32 field cannot carry 1e300:
rospy would refuse it in the caller before anything reaches the node), but covers the rest of the type:
NaN, +-inf, -0.0, subnormals, the type's extremes, huge and tiny magnitudes, and for strings the empty
string, very long text, unicode, control characters and near-misses of the words the service accepts.
"""
import html
import math

import numpy
from hypothesis import strategies as st

FLOAT32_MAX = float(numpy.finfo(numpy.float32).max)
FLOAT32_TINY = float(numpy.finfo(numpy.float32).smallest_subnormal)
LONG_TEXT_CHARS = 100_000
UTF8 = st.characters(codec="utf-8")
"""Any character a str field can carry (rospy encodes str as UTF-8, so lone surrogates cannot be sent)."""

_SPECIAL_FLOATS = [math.nan, -math.nan, math.inf, -math.inf, 0.0, -0.0, -1.0, 1e-300, -1e-300, 5e-324,
                   1e300, -1e300, 1.7976931348623157e308, -1.7976931348623157e308]
_SPECIAL_FLOATS32 = [math.nan, math.inf, -math.inf, 0.0, -0.0, -1.0, FLOAT32_TINY, -FLOAT32_TINY, 1e-30,
                     1e30, -1e30, FLOAT32_MAX, -FLOAT32_MAX]


def float64s():
    """Any float64, with the special values above drawn often."""
    return st.one_of(st.sampled_from(_SPECIAL_FLOATS), st.floats(allow_nan=True, allow_infinity=True))


def float32s():
    """Any value a float32 field can carry, with its special values drawn often."""
    return st.one_of(st.sampled_from(_SPECIAL_FLOATS32), st.floats(width=32, allow_nan=True, allow_infinity=True))


def signed_ints(bits):
    """Any integer of a signed `bits`-bit field, extremes and their neighbours drawn often."""
    low, high = -2 ** (bits - 1), 2 ** (bits - 1) - 1
    return st.one_of(st.sampled_from([low, low + 1, -1, 0, 1, high - 1, high]), st.integers(low, high))


def uint8s():
    return st.integers(0, 255)


def _near_misses(word):
    """Words a person might type for `word`: other case, padding, typos, look-alike letters, junk around it."""
    cyrillic_lookalikes = str.maketrans("aceopx", "асеорх")
    return st.sampled_from([
        word.upper(), word.lower(), word.title(), " " + word, word + " ", "\t" + word + "\n", word + "\0",
        word * 2, word[:-1], word[1:], word + "s", word.replace(" ", ""), word.replace(" ", "_"),
        word.translate(cyrillic_lookalikes), "'" + word + "'", '"' + word + '"', word + ";rm -rf /",
    ])


def texts(valid_words=()):
    """Strings: the service's own words (so some requests are valid), near-misses of them, empty, unicode,
    control characters, format specifiers and very long text."""
    candidates = [
        st.text(UTF8, max_size=40),
        st.text(st.characters(min_codepoint=0x80, codec="utf-8"), max_size=20),
        st.sampled_from(["", " ", "\0", "%s%s%n", "{}", "\\", "\n", "None", "null", "true", "0", "-1", "NaN",
                         "💥", "a" * LONG_TEXT_CHARS, "ü" * LONG_TEXT_CHARS]),
    ]
    if valid_words:
        candidates += [st.sampled_from(list(valid_words)),
                       st.sampled_from(list(valid_words)).flatmap(_near_misses)]
    return st.one_of(candidates)


def graph_names():
    """Strings from the ROS graph-name alphabet (valid and invalid names: '/', '~', '_', digits first...)."""
    return st.one_of(st.text(alphabet="ab1_/~", max_size=8), texts())


def number_texts():
    """Numbers as they appear in XML attributes and elements, including ones float() reads as nan/inf."""
    return st.one_of(float64s().map(repr), st.sampled_from(
        ["nan", "inf", "-inf", "1e999", "-0", "0", "", " ", "abc", "1,5", "0x10", "1 2", "1e-45", "1e-400"]))


def lengths():
    """Lengths in metres as XML text: any number text, a sensible size, or a plausible-looking length from a
    micrometre to a light-second (what a unit mistake produces)."""
    return st.one_of(number_texts(), st.floats(0.01, 2.0).map(repr), st.floats(1e-6, 3e8).map(repr),
                     st.sampled_from(["1e-30", "1e-4", "0.001", "1e10", "1e30", "1e39", "1e300"]))


def _sizes(count):
    cube = lengths().map(lambda length: " ".join([length] * count))
    return st.one_of(cube, st.lists(lengths(), min_size=count, max_size=count).map(" ".join))


def _sdf_geometry():
    return st.one_of(
        st.builds("<box><size>{}</size></box>".format, st.one_of(_sizes(3), _sizes(2), lengths())),
        st.builds("<cylinder><radius>{}</radius><length>{}</length></cylinder>".format, lengths(), lengths()),
        st.builds("<sphere><radius>{}</radius></sphere>".format, lengths()),
        st.sampled_from(["<mesh><uri>model://x.dae</uri></mesh>", "<plane/>", "", "<box/>", "<box></box><box/>"]))


def _urdf_geometry():
    return st.one_of(
        st.builds("<box size='{}'/>".format, st.one_of(_sizes(3), lengths())),
        st.builds("<cylinder radius='{}' length='{}'/>".format, lengths(), lengths()),
        st.builds("<sphere radius='{}'/>".format, lengths()),
        st.sampled_from(["<mesh filename='x.stl'/>", "", "<box/>"]))


def _xml_name():
    return st.one_of(st.sampled_from(["", "fuzzed", "turtlebot3_waffle", "ground_plane"]),
                     st.text(UTF8, max_size=12).map(lambda text: html.escape(text, quote=True)))


_SDF = ("<sdf version='1.6'><model name='{}'><static>{}</static><pose>{}</pose><link name='l'><inertial><mass>{}"
        "</mass></inertial><collision name='c'><geometry>{}</geometry></collision></link></model></sdf>")
_URDF = ("<robot name='{}'><link name='l'><inertial><mass value='{}'/></inertial><collision><origin xyz='{}' "
         "rpy='{}'/><geometry>{}</geometry></collision></link>{}</robot>")


def sdf_documents(everything=False):
    """SDF models of the shape tb3_sim reads with a fuzzed geometry; `everything`: names, pose and mass too."""
    if not everything:
        return st.builds(_SDF.format, st.just("fuzzed"), st.just("false"), st.just("0 0 0 0 0 0"), st.just("1"),
                         _sdf_geometry())
    return st.builds(_SDF.format, _xml_name(), st.sampled_from(["true", "false", "1", "yes", ""]),
                     st.one_of(_sizes(6), _sizes(3)), number_texts(), _sdf_geometry())


def urdf_documents(everything=False):
    """URDF robots of the shape tb3_sim reads with a fuzzed geometry; `everything`: name, origin and mass too."""
    if not everything:
        return st.builds(_URDF.format, st.just("fuzzed"), st.just("1"), st.just("0 0 0"), st.just("0 0 0"),
                         _urdf_geometry(), st.just(""))
    return st.builds(_URDF.format, _xml_name(), number_texts(), _sizes(3), _sizes(3), _urdf_geometry(),
                     st.sampled_from(["", "<gazebo><static>true</static></gazebo>", "<gazebo><static/></gazebo>"]))


_HOSTILE_XML = [
    "<!DOCTYPE r [<!ENTITY a 'aaaaaaaaaa'><!ENTITY b '&a;&a;&a;&a;&a;&a;&a;&a;&a;&a;'>"
    "<!ENTITY c '&b;&b;&b;&b;&b;&b;&b;&b;&b;&b;'><!ENTITY d '&c;&c;&c;&c;&c;&c;&c;&c;&c;&c;'>"
    "<!ENTITY e '&d;&d;&d;&d;&d;&d;&d;&d;&d;&d;'><!ENTITY f '&e;&e;&e;&e;&e;&e;&e;&e;&e;&e;'>]>"
    "<robot name='&f;'/>",
    "<!DOCTYPE r [<!ENTITY x SYSTEM 'file:///etc/passwd'>]><robot name='&x;'/>",
    "<sdf>" * 5000 + "</sdf>" * 5000,
    "<robot name='a' name='b'/>", "<robot>", "</robot>", "<?xml version='1.0'?>", "<sdf><model/></sdf>",
]


def model_xml_models():
    """Well-formed SDF and URDF models with fuzzed sizes, so that requests reach the physics."""
    return st.one_of(sdf_documents(), urdf_documents())


def model_xml_garbage():
    """Everything else a spawn service may be sent: models with every field fuzzed, the same cut short at
    any character, random text, and hostile XML (an entity bomb, an external entity, deep nesting)."""
    everything = st.one_of(sdf_documents(everything=True), urdf_documents(everything=True))
    truncated = st.tuples(everything, st.integers(0, 400)).map(lambda pair: pair[0][:pair[1]])
    return st.one_of(everything, truncated, texts(), st.sampled_from(_HOSTILE_XML))
