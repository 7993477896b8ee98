"""SDF/URDF spawn payloads -> ModelSpec: the shapes, poses and flags course code sends, and clear refusals."""
import math

import pytest

from tb3_sim.core.errors import ModelXmlError, NotModelXmlError, NotUrdfError
from tb3_sim.core.geometry import Pose2D
from tb3_sim.core.model_xml import box_sdf, compose, parse_model_xml
from tb3_sim.core.shapes import Box, Cylinder

SDF_BOX = """<?xml version="1.0"?>
<!-- as the Gazebo box tool writes it -->
<sdf version="1.6">
  <model name="unit_box">
    <static>true</static>
    <pose>1.0 2.0 0.25 0 0 1.5707963</pose>
    <link name="link">
      <inertial><mass>2.5</mass></inertial>
      <collision name="collision"><geometry><box><size>0.3 0.4 0.5</size></box></geometry></collision>
      <visual name="visual"><geometry><box><size>0.3 0.4 0.5</size></box></geometry></visual>
    </link>
  </model>
</sdf>"""

URDF_CYLINDER = """<robot name="can">
  <link name="base">
    <inertial><mass value="0.2"/></inertial>
    <collision><origin xyz="0.5 0 0.1" rpy="0 0 0.3"/><geometry><cylinder radius="0.05" length="0.2"/></geometry>
    </collision>
  </link>
  <gazebo><static>true</static></gazebo>
</robot>"""


def sdf_with(geometry, extra=""):
    return (f"<sdf version='1.6'><model name='m'>{extra}<link name='l'><collision name='c'><geometry>{geometry}"
            "</geometry></collision></link></model></sdf>")


def test_sdf_box_gives_name_shape_pose_static_and_mass():
    spec = parse_model_xml(SDF_BOX)
    assert spec.name == "unit_box"
    assert spec.shape == Box(0.3, 0.4, 0.5)
    assert spec.pose == pytest.approx(Pose2D(1.0, 2.0, 1.5707963))
    assert spec.static and spec.mass_kg == 2.5


def test_sdf_link_and_collision_poses_fold_into_the_model_pose():
    text = ("<sdf><model name='m'><pose>1 0 0 0 0 1.5707963267948966</pose><link name='l'><pose>1 0 0 0 0 0"
            "</pose><collision name='c'><pose>0 1 0 0 0 0</pose><geometry><sphere><radius>0.1</radius>"
            "</sphere></geometry></collision></link></model></sdf>")
    spec = parse_model_xml(text)
    assert (spec.pose.x, spec.pose.y, spec.pose.yaw) == pytest.approx((0.0, 1.0, math.pi / 2))


def test_sdf_cylinder_and_sphere():
    cylinder = parse_model_xml(sdf_with("<cylinder><radius>0.1</radius><length>0.5</length></cylinder>"))
    assert cylinder.shape == Cylinder(0.1, 0.5)
    sphere = parse_model_xml(sdf_with("<sphere><radius>0.2</radius></sphere>"))
    assert sphere.shape == Cylinder(0.2, 0.4)


def test_defaults_dynamic_one_kilogram_at_the_origin():
    spec = parse_model_xml(sdf_with("<box><size>1 1 1</size></box>"))
    assert (spec.static, spec.mass_kg, spec.pose) == (False, 1.0, Pose2D())


def test_legacy_gazebo_root_is_sdf():
    text = ("<gazebo><model name='old'><link name='l'><collision name='c'><geometry><box><size>1 1 1</size>"
            "</box></geometry></collision></link></model></gazebo>")
    assert parse_model_xml(text).name == "old"


def test_urdf_cylinder_with_origin_mass_and_static():
    spec = parse_model_xml(URDF_CYLINDER, urdf_only=True)
    assert spec.name == "can"
    assert spec.shape == Cylinder(0.05, 0.2)
    assert spec.pose == pytest.approx(Pose2D(0.5, 0.0, 0.3))
    assert spec.static and spec.mass_kg == 0.2


def test_urdf_box_and_sphere():
    box = parse_model_xml("<robot name='b'><link name='l'><collision><geometry><box size='0.1 0.2 0.3'/>"
                          "</geometry></collision></link></robot>")
    assert box.shape == Box(0.1, 0.2, 0.3) and not box.static
    sphere = parse_model_xml("<robot name='s'><link name='l'><collision><geometry><sphere radius='0.1'/>"
                             "</geometry></collision></link></robot>")
    assert sphere.shape == Cylinder(0.1, 0.2)


def test_box_sdf_reads_back():
    spec = parse_model_xml(box_sdf("box1", 0.3, 0.3, 0.4, static=True, mass_kg=3.0))
    assert (spec.name, spec.shape, spec.static, spec.mass_kg) == ("box1", Box(0.3, 0.3, 0.4), True, 3.0)


def test_compose_rotates_the_child_into_the_parent():
    assert compose(Pose2D(1.0, 1.0, math.pi / 2), Pose2D(1.0, 0.0, 0.5)) == pytest.approx(
        Pose2D(1.0, 2.0, math.pi / 2 + 0.5))


@pytest.mark.parametrize("text, error, message", [
    ("<sdf><model", NotModelXmlError, "XML syntax error"),
    ("not xml at all", NotModelXmlError, "XML syntax error"),
    ("<world name='w'/>", NotModelXmlError, r"root element is <world>; expected <sdf> or <robot>"),
    ("<sdf version='1.6'/>", ModelXmlError, "<sdf> has no <model>"),
    (sdf_with("<mesh><uri>x.dae</uri></mesh>"), ModelXmlError, r"unsupported geometry <mesh>"),
    (sdf_with("<box><size>1 1</size></box>"), ModelXmlError, r"<box><size> must be 3 positive numbers, got '1 1'"),
    (sdf_with("<box><size>1 -1 1</size></box>"), ModelXmlError, "positive numbers"),
    (sdf_with("<cylinder><radius>0.1</radius></cylinder>"), ModelXmlError, r"<cylinder><length>"),
    (sdf_with("<box><size>1 1 1</size></box>", "<pose>0 0 0 1.57 0 0</pose>"), ModelXmlError, "yaw only"),
    ("<sdf><model name='m'><link name='l'/></model></sdf>", ModelXmlError, r"model 'm' has no <collision>"),
    (sdf_with("<box><size>1 1 1</size></box><sphere><radius>1</radius></sphere>"), ModelXmlError,
     "one shape"),
    ("<robot name='r'><link name='a'><collision><geometry><sphere radius='1'/></geometry></collision>"
     "<collision><geometry><sphere radius='1'/></geometry></collision></link></robot>", ModelXmlError,
     r"2 <collision> elements"),
    ("<robot name='r'><link name='a'><collision><geometry><box size='a b c'/></geometry></collision></link>"
     "</robot>", ModelXmlError, r"<box size> must be 3 positive numbers"),
    ("<robot name='r'><link name='a'><inertial><mass value='0'/></inertial><collision><geometry>"
     "<sphere radius='1'/></geometry></collision></link></robot>", ModelXmlError, "mass"),
])
def test_bad_payloads_are_refused_with_the_reason(text, error, message):
    with pytest.raises(error, match=message):
        parse_model_xml(text)


def test_urdf_service_refuses_sdf():
    with pytest.raises(NotUrdfError, match=r"root element is <sdf>, not <robot>"):
        parse_model_xml(SDF_BOX, urdf_only=True)


@pytest.mark.parametrize("geometry, message", [
    ("<box><size>1e-300 1e-300 1e-300</size></box>", r"<box><size> = 1e-300 m is outside \[0.001, 100\] m"),
    ("<box><size>1 1 1e300</size></box>", r"<box><size> = 1e\+300 m is outside"),
    ("<sphere><radius>0.0001</radius></sphere>", r"<sphere><radius> = 0.0001 m is outside"),
])
def test_degenerate_and_huge_sizes_are_refused(geometry, message):
    with pytest.raises(ModelXmlError, match=message):
        parse_model_xml(sdf_with(geometry))


def test_absurd_mass_is_refused():
    text = ("<robot name='r'><link name='a'><inertial><mass value='1e-300'/></inertial><collision><geometry>"
            "<sphere radius='1'/></geometry></collision></link></robot>")
    with pytest.raises(ModelXmlError, match=r"= 1e-300 kg is outside \[1e-06, 1e\+06\] kg"):
        parse_model_xml(text)


def sdf_box(material):
    return (f'<sdf version="1.6"><model name="b"><link name="l"><collision name="c"><geometry><box><size>0.3 0.3 0.3'
            f'</size></box></geometry></collision><visual name="v"><geometry><box><size>0.3 0.3 0.3</size></box>'
            f'</geometry><material>{material}</material></visual></link></model></sdf>')


def urdf_box(extra="", visual_material=""):
    return (f'<robot name="b">{extra}<link name="l"><visual><geometry><box size="0.3 0.3 0.3"/></geometry>'
            f'{visual_material}</visual><collision><geometry><box size="0.3 0.3 0.3"/></geometry></collision>'
            f'</link></robot>')


@pytest.mark.parametrize("text, rgb", [
    (sdf_box("<script><name>Gazebo/Red</name></script>"), (255, 0, 0)),
    (sdf_box("<ambient>0 0 1 1</ambient><diffuse>0 1 0 1</diffuse>"), (0, 255, 0)),
    (sdf_box("<ambient>0 0 1 1</ambient>"), (0, 0, 255)),
    (sdf_box("<script><name>Gazebo/NoSuchMaterial</name></script>"), None),
    (urdf_box(visual_material='<material name="m"><color rgba="1 1 0 1"/></material>'), (255, 255, 0)),
    (urdf_box(extra='<material name="blue"><color rgba="0 0 1 1"/></material>',
              visual_material='<material name="blue"/>'), (0, 0, 255)),
    (urdf_box(extra='<gazebo reference="l"><material>Gazebo/Red</material></gazebo>',
              visual_material='<material name="m"><color rgba="0 0 1 1"/></material>'), (255, 0, 0)),
    (urdf_box(), None),
])
def test_model_colours_as_gazebo_reads_them(text, rgb):
    assert parse_model_xml(text).rgb == rgb


def test_malformed_colour_numbers_are_an_error():
    with pytest.raises(ModelXmlError, match="<material><diffuse>"):
        parse_model_xml(sdf_box("<diffuse>red</diffuse>"))
