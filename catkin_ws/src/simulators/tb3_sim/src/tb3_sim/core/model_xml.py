"""Minimal SDF and URDF readers for /gazebo/spawn_sdf_model and spawn_urdf_model: XML text -> ModelSpec.

Supported, which is what course code and the Gazebo box tool send:
- SDF: <sdf> (or legacy <gazebo>) holding one <model name=...> with optional <static> and <pose>, links with
  optional <pose> and <inertial><mass>, and <collision> elements with optional <pose> and a <geometry> of
  <box><size>x y z</size></box>, <cylinder><radius/><length/></cylinder> or <sphere><radius/></sphere>.
- URDF: <robot name=...> with links holding <collision><origin xyz rpy/><geometry><box size="x y z"/> |
  <cylinder radius length/> | <sphere radius/></geometry></collision> and optional <inertial><mass value/>;
  <gazebo><static>true</static></gazebo> makes the model static.
A model must have exactly one collision shape. Units: metres, radians, kilograms.
- A TurtleBot3: a URDF whose robot name is turtlebot3_burger, turtlebot3_waffle or turtlebot3_waffle_pi (what
  xacro makes of turtlebot3_description's files) is read as that robot, a `TurtleBot3Spec`, whatever its links.

Colour (what the camera sees), from the first that is given: SDF <visual><material> with <diffuse>, else
<ambient> (r g b [a], each in [0, 1]), else <script><name>Gazebo/Red</name>; URDF <gazebo><material>Gazebo/Red
</material></gazebo> (for the whole robot or the link's reference), else <visual><material> with <color rgba>
or the name of a top-level <material> that has one. A Gazebo material this table does not know renders in
Gazebo's default grey, as Gazebo falls back when a material script is missing; malformed colour numbers are an
error.

2D simplifications, kept on purpose: z is ignored (objects rest on the floor; a box's height is its z size, a
cylinder's its length, a sphere's its diameter); roll and pitch must be zero; the link and collision offsets are
folded into the model pose, so the model origin reported by get_model_state is the collision shape's centre;
a link without <inertial> weighs 1 kg, as in Gazebo. Sizes must lie within [MIN_SHAPE_SIZE_M,
MAX_SHAPE_SIZE_M] (1 mm to 100 m) and masses within [MIN_MASS_KG, MAX_MASS_KG]; Gazebo has no such limits.
"""

import math
import xml.etree.ElementTree as ElementTree
from dataclasses import dataclass, replace

from tb3_sim.core.errors import ModelXmlError, NotModelXmlError, NotUrdfError
from tb3_sim.core.geometry import Pose2D, wrap_angle
from tb3_sim.core.materials import material_rgb, rgba_text_to_rgb
from tb3_sim.core.shapes import Box, Cylinder
from tb3_sim.core.turtlebot3 import TurtleBot3Model, model_of_robot_name
from tb3_sim.core.world_file import DEFAULT_MODEL_MASS_KG, ModelSpec

# Sanity limits: Box2D works in float32 and needs non-degenerate shapes; anything outside is refused.
MIN_SHAPE_SIZE_M = 0.001
MAX_SHAPE_SIZE_M = 100.0
MIN_MASS_KG = 1e-6
MAX_MASS_KG = 1e6

SDF_ROOTS = ("sdf", "gazebo")
URDF_ROOT = "robot"
TILT_TOLERANCE_RAD = 1e-6
TRUE_WORDS = ("true", "1")


@dataclass(frozen=True)
class TurtleBot3Spec:
    """A TurtleBot3 to spawn: its name (the URDF's robot name; the caller may override it), its `model` and its
    pose (the URDF's root has none: the origin)."""

    name: str
    model: TurtleBot3Model
    pose: Pose2D = Pose2D()


def compose(parent, child):
    """The pose `child`, given in the frame `parent`, expressed in the parent's own frame (2D)."""
    x, y = parent.compose(child.x, child.y)
    return Pose2D(x, y, wrap_angle(parent.yaw + child.yaw))


def parse_model_xml(text, urdf_only=False):
    """The ModelSpec (or TurtleBot3Spec) described by SDF or URDF `text`, at its pose in the XML (compose with
    the spawn pose).

    The name is the XML's model or robot name (may be empty; the caller may override it). Raises
    NotModelXmlError (not XML, or neither SDF nor URDF), NotUrdfError (`urdf_only` and not URDF), or
    ModelXmlError naming the element that is missing, malformed or unsupported.
    """
    try:
        root = ElementTree.fromstring(text)
    except ElementTree.ParseError as error:
        raise NotModelXmlError(f"XML syntax error: {error}") from None
    if urdf_only and root.tag != URDF_ROOT:
        raise NotUrdfError(f"the root element is <{root.tag}>, not <robot>")
    if root.tag == URDF_ROOT:
        return _parse_urdf(root)
    if root.tag in SDF_ROOTS:
        return _parse_sdf(root)
    raise NotModelXmlError(f"the root element is <{root.tag}>; expected <sdf> or <robot>")


def _parse_sdf(root):
    model = root.find("model")
    if model is None:
        raise ModelXmlError(f"<{root.tag}> has no <model> element")
    model_pose = _sdf_pose(model)
    static = _text(model, "static", "false").lower() in TRUE_WORDS
    found = []
    for link in model.findall("link"):
        link_pose = compose(model_pose, _sdf_pose(link))
        mass = _mass(_text(link, "inertial/mass", None), "<link><inertial><mass>")
        rgb = _sdf_colour(link)
        for collision in link.findall("collision"):
            shape = _sdf_geometry(collision.find("geometry"))
            found.append((shape, compose(link_pose, _sdf_pose(collision)), mass, rgb))
    return _single_shape(model.get("name", ""), found, static)


def _parse_urdf(root):
    turtlebot3 = model_of_robot_name(root.get("name", ""))
    if turtlebot3 is not None:
        return TurtleBot3Spec(root.get("name"), turtlebot3)
    found = []
    for link in root.findall("link"):
        mass_element = link.find("inertial/mass")
        mass = _mass(None if mass_element is None else mass_element.get("value"), "<inertial><mass value>")
        rgb = _urdf_colour(root, link)
        for collision in link.findall("collision"):
            shape = _urdf_geometry(collision.find("geometry"))
            found.append((shape, _urdf_origin(collision.find("origin")), mass, rgb))
    static = any((element.text or "").strip().lower() in TRUE_WORDS for element in root.findall("gazebo/static"))
    return _single_shape(root.get("name", ""), found, static)


def _single_shape(name, found, static):
    if len(found) != 1:
        what = "no <collision>" if not found else f"{len(found)} <collision> elements"
        raise ModelXmlError(f"model '{name}' has {what}; tb3_sim needs exactly one box, cylinder or sphere")
    shape, pose, mass, rgb = found[0]
    return ModelSpec(name, shape, pose, static, mass, rgb)


def _gazebo_material(name):
    """The colour of a Gazebo material script name, or None (default grey) if the table does not know it."""
    try:
        return material_rgb(name)
    except ValueError:
        return None


def _rgba(text, what):
    try:
        return rgba_text_to_rgb(text)
    except ValueError as error:
        raise ModelXmlError(f"{what}: {error}") from None


def _sdf_colour(link):
    for material in link.findall("visual/material"):
        for channel in ("diffuse", "ambient"):
            text = _text(material, channel, None)
            if text is not None:
                return _rgba(text, f"<material><{channel}>")
        script = _text(material, "script/name", None)
        if script is not None:
            return _gazebo_material(script)
    return None


def _urdf_colour(root, link):
    for gazebo in root.findall("gazebo"):
        if gazebo.get("reference") in (None, link.get("name")) and _text(gazebo, "material", None):
            return _gazebo_material(_text(gazebo, "material", None))
    named = {m.get("name"): m for m in root.findall("material")}
    for material in link.findall("visual/material"):
        color = material.find("color")
        if color is None:
            color = named.get(material.get("name"), material).find("color")
        if color is not None:
            return _rgba(color.get("rgba"), "<material><color rgba>")
    return None


def with_name(spec, name):
    """`spec` renamed (the request's model_name overrides the XML's)."""
    return replace(spec, name=name)


def _text(element, path, default):
    found = element.find(path)
    return default if found is None or found.text is None else found.text.strip()


def _numbers(text, count, what, positive=False):
    try:
        values = [float(v) for v in (text or "").split()]
    except ValueError:
        values = []
    if len(values) != count or not all(math.isfinite(v) for v in values) or (
            positive and not all(v > 0 for v in values)):
        kind = "positive numbers" if positive else "numbers"
        raise ModelXmlError(f"{what} must be {count} {kind}, got {text!r}")
    return values


def _pose6(x, y, roll, pitch, yaw, what):
    if abs(wrap_angle(roll)) > TILT_TOLERANCE_RAD or abs(wrap_angle(pitch)) > TILT_TOLERANCE_RAD:
        raise ModelXmlError(f"{what} has roll or pitch; tb3_sim is 2D and supports yaw only")
    return Pose2D(x, y, wrap_angle(yaw))


def _sdf_pose(element):
    text = _text(element, "pose", None)
    if text is None:
        return Pose2D()
    x, y, _, roll, pitch, yaw = _numbers(text, 6, f"<{element.tag}><pose>")
    return _pose6(x, y, roll, pitch, yaw, f"<{element.tag}><pose>")


def _urdf_origin(origin):
    if origin is None:
        return Pose2D()
    x, y, _ = _numbers(origin.get("xyz", "0 0 0"), 3, "<origin xyz>")
    roll, pitch, yaw = _numbers(origin.get("rpy", "0 0 0"), 3, "<origin rpy>")
    return _pose6(x, y, roll, pitch, yaw, "<collision><origin>")


def _mass(text, what):
    if text is None:
        return DEFAULT_MODEL_MASS_KG
    mass = _numbers(text, 1, what, positive=True)[0]
    if not MIN_MASS_KG <= mass <= MAX_MASS_KG:
        raise ModelXmlError(f"{what} = {mass:g} kg is outside [{MIN_MASS_KG:g}, {MAX_MASS_KG:g}] kg")
    return mass


def _sizes(text, count, what):
    values = _numbers(text, count, what, positive=True)
    for value in values:
        if not MIN_SHAPE_SIZE_M <= value <= MAX_SHAPE_SIZE_M:
            raise ModelXmlError(f"{what} = {value:g} m is outside [{MIN_SHAPE_SIZE_M:g}, {MAX_SHAPE_SIZE_M:g}] m")
    return values


def _only_child(geometry, where):
    if geometry is None or len(geometry) != 1:
        raise ModelXmlError(f"{where} needs a <geometry> with one shape")
    return geometry[0]


def _sdf_geometry(geometry):
    shape = _only_child(geometry, "<collision>")
    if shape.tag == "box":
        return Box(*_sizes(_text(shape, "size", None), 3, "<box><size>"))
    if shape.tag == "cylinder":
        radius = _sizes(_text(shape, "radius", None), 1, "<cylinder><radius>")[0]
        return Cylinder(radius, _sizes(_text(shape, "length", None), 1, "<cylinder><length>")[0])
    if shape.tag == "sphere":
        return Cylinder.sphere(_sizes(_text(shape, "radius", None), 1, "<sphere><radius>")[0])
    raise ModelXmlError(f"unsupported geometry <{shape.tag}>; use <box>, <cylinder> or <sphere>")


def _urdf_geometry(geometry):
    shape = _only_child(geometry, "<collision>")
    if shape.tag == "box":
        return Box(*_sizes(shape.get("size"), 3, "<box size>"))
    if shape.tag == "cylinder":
        radius = _sizes(shape.get("radius"), 1, "<cylinder radius>")[0]
        return Cylinder(radius, _sizes(shape.get("length"), 1, "<cylinder length>")[0])
    if shape.tag == "sphere":
        return Cylinder.sphere(_sizes(shape.get("radius"), 1, "<sphere radius>")[0])
    raise ModelXmlError(f"unsupported geometry <{shape.tag}>; use <box>, <cylinder> or <sphere>")


def box_sdf(name, size_x, size_y, height, static=False, mass_kg=DEFAULT_MODEL_MASS_KG, rgb=None):
    """SDF text of a box model like the one Gazebo's box tool inserts: one link, one collision, one visual; with
    `rgb` ((r, g, b) 0-255) the visual gets that colour as its ambient and diffuse material."""
    size = f"{size_x:g} {size_y:g} {height:g}"
    geometry = f"<geometry><box><size>{size}</size></box></geometry>"
    material = ""
    if rgb is not None:
        rgba = " ".join(f"{channel / 255:g}" for channel in rgb) + " 1"
        material = f"<material><ambient>{rgba}</ambient><diffuse>{rgba}</diffuse></material>"
    return (f'<?xml version="1.0"?>\n<sdf version="1.6"><model name="{name}">'
            f"<static>{str(bool(static)).lower()}</static><link name=\"link\">"
            f"<inertial><mass>{mass_kg:g}</mass></inertial>"
            f"<collision name=\"collision\">{geometry}</collision>"
            f"<visual name=\"visual\">{geometry}{material}</visual>"
            "</link></model></sdf>")
