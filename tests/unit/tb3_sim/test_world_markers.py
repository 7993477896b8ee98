"""rviz markers of the world: one per static shape and model, each robot's body, placed and sized as the
physics has them."""
import math

import pytest
import rospy
from visualization_msgs.msg import Marker

from tb3_sim.core import load_world, shipped_world_path
from tb3_sim.core.geometry import Pose2D
from tb3_sim.core.shapes import Box, Circle, Cylinder, Polygon, Segment
from tb3_sim.core.turtlebot3 import BURGER, WAFFLE
from tb3_sim.ros.outputs.world_markers import MarkedModel, world_markers
from tb3_sim.view.scene import ModelView

STAMP = rospy.Time(12, 0)


def test_first_marker_clears_old_ones():
    assert world_markers((), (), (), STAMP).markers[0].action == Marker.DELETEALL


def test_convex_polygon_becomes_a_fan_of_triangles_at_its_height():
    square = Polygon(points=((0, 0), (1, 0), (1, 1), (0, 1)), height=0.5)
    marker = world_markers((square,), (), (), STAMP).markers[1]
    assert marker.type == Marker.TRIANGLE_LIST and marker.ns == "static"
    assert len(marker.points) == 6
    assert {(p.x, p.y, p.z) for p in marker.points} == {(0, 0, 0.5), (1, 0, 0.5), (1, 1, 0.5), (0, 1, 0.5)}


def test_circle_and_segment():
    circle, segment = Circle(center=(2.0, -1.0), radius=0.15, height=0.5), Segment(start=(0, 0), end=(3, 0))
    pillar, wall = world_markers((circle, segment), (), (), STAMP).markers[1:3]
    assert pillar.type == Marker.CYLINDER
    assert (pillar.pose.position.x, pillar.pose.position.y, pillar.pose.position.z) == (2.0, -1.0, 0.25)
    assert (pillar.scale.x, pillar.scale.z) == pytest.approx((0.3, 0.5))
    assert wall.type == Marker.LINE_LIST and [(p.x, p.y) for p in wall.points] == [(0, 0), (3, 0)]


def test_models_at_their_pose_with_their_size():
    box = ModelView("box1", Box(size_x=0.4, size_y=0.2, height=0.3), Pose2D(1.5, 0.5, math.pi / 2), False)
    can = ModelView("can", Cylinder(radius=0.1, height=0.5), Pose2D(-1.0, 0.0, 0.0), True)
    cube, cylinder = world_markers((), (box, can), (), STAMP).markers[1:3]
    assert (cube.type, cube.text, cube.ns) == (Marker.CUBE, "box1", "models")
    assert (cube.scale.x, cube.scale.y, cube.scale.z) == pytest.approx((0.4, 0.2, 0.3))
    assert 2 * math.atan2(cube.pose.orientation.z, cube.pose.orientation.w) == pytest.approx(math.pi / 2)
    assert (cylinder.type, cylinder.scale.x, cylinder.pose.position.z) == (Marker.CYLINDER, pytest.approx(0.2), 0.25)


def test_each_robot_body_at_its_pose_with_its_model_size():
    waffle = MarkedModel("tb3_0", WAFFLE, Pose2D(1.0, 2.0, math.pi / 2))
    burger = MarkedModel("tb3_1", BURGER, Pose2D(-1.0, 0.0, 0.0))
    first, second = world_markers((), (), (waffle, burger), STAMP).markers[1:]
    assert (first.ns, first.text, first.header.frame_id) == ("robots", "tb3_0", "odom")
    assert (first.scale.x, first.scale.y) == pytest.approx((0.266, 0.266))
    assert (first.pose.position.x, first.pose.position.y) == pytest.approx((1.0, 2.0 - 0.064))
    assert first.pose.position.z == pytest.approx((0.010 + 0.104) / 2)
    assert (second.scale.x, second.scale.y, second.pose.position.x) == pytest.approx((0.14, 0.14, -1.032))


def test_shipped_world_has_one_marker_per_shape():
    world = load_world(shipped_world_path("turtlebot3_world"))
    markers = world_markers(world.static_shapes, (), (), STAMP).markers
    assert len(markers) == 1 + len(world.static_shapes)
    assert all(marker.header.frame_id == "odom" for marker in markers[1:])
    assert all(marker.header.stamp == STAMP for marker in markers[1:])
