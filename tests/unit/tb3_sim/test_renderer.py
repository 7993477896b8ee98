"""The headless top-down view: Trail, Scene and the QPainter renderer's pixels (no display, no ROS)."""
import pytest
from PyQt5.QtGui import QColor, QImage

from tb3_sim.core.geometry import Pose2D
from tb3_sim.core.lidar import Lidar
from tb3_sim.core.shapes import Box
from tb3_sim.core.world import World
from tb3_sim.core.world_file import ModelSpec, load_world, shipped_world_path
from tb3_sim.view import renderer
from tb3_sim.view.renderer import View, render_image, save_png
from tb3_sim.view.scene import Trail, Trails, scene_of


@pytest.fixture
def world():
    world = World(load_world(shipped_world_path("turtlebot3_world")), Pose2D(-2.0, -0.5, 0.0))
    world.spawn_model(ModelSpec("box1", Box(0.4, 0.4, 0.4), Pose2D(-1.0, -0.5, 0.0)))
    return world


def colour_at(image, view, x, y):
    column, row = view.to_pixel(x, y)
    return QColor(image.pixel(int(column), int(row))).rgb()


def test_trail_keeps_points_a_spacing_apart():
    trail = Trail(spacing_m=0.3)
    for i in range(5):
        trail.add(i * 0.25, 0.0)
    assert trail.strokes() == (((0.0, 0.0), (0.5, 0.0), (1.0, 0.0)),)


def test_trail_jump_starts_a_new_stroke_and_clear_empties_it():
    trail = Trail(spacing_m=0.01, jump_m=0.5)
    trail.add(0.0, 0.0)
    trail.add(0.1, 0.0)
    trail.add(3.0, 0.0)
    assert trail.strokes() == (((0.0, 0.0), (0.1, 0.0)), ((3.0, 0.0),))
    trail.clear()
    assert trail.strokes() == ()


def test_trail_drops_the_oldest_points():
    trail = Trail(spacing_m=0.01, max_points=3, jump_m=0.5)
    for x in (0.0, 0.1, 2.0, 2.1):
        trail.add(x, 0.0)
    assert trail.strokes() == (((0.1, 0.0),), ((2.0, 0.0), (2.1, 0.0)))
    trail.add(2.2, 0.0)
    assert trail.strokes() == (((2.0, 0.0), (2.1, 0.0), (2.2, 0.0)),)


def test_scene_copies_models_robot_and_scan_hits(world):
    scene = scene_of(world, Trails(), Lidar().read(world, world.robot, world.time_s))
    assert [m.name for m in scene.models] == ["box1"]
    assert [(r.name, r.pose) for r in scene.robots] == [("turtlebot3_waffle", pytest.approx(Pose2D(-2.0, -0.5, 0.0)))]
    hits = scene.scan_hits()
    assert len(hits) > 100
    ahead = hits[abs(hits[:, 1] + 0.5) < 0.01]
    assert ahead[:, 0].max() == pytest.approx(-1.2, abs=0.05)


def test_view_fits_the_whole_arena():
    scene = scene_of(World(load_world(shipped_world_path("turtlebot3_world")), Pose2D(-2.0, -0.5, 0.0)), Trails())
    view = View.fit(scene, 800, 600)
    for x, y in ((-3.3, 0.0), (4.67, 0.0), (0.0, 3.4), (0.0, -3.4)):
        column, row = view.to_pixel(x, y)
        assert 0 < column < 800 and 0 < row < 600


def test_pixels_show_robot_walls_models_and_rays(world):
    trails = Trails()
    trails.add(world.robots())
    image, view = render_image(scene_of(world, trails, Lidar().read(world, world.robot, world.time_s)), 800, 800)
    assert colour_at(image, view, -2.05, -0.5) == renderer.ROBOT_FILL.rgb()
    assert colour_at(image, view, 0.0, 0.0) == renderer.STATIC_FILL.rgb()
    assert colour_at(image, view, -1.0, -0.4) == renderer.MODEL_FILL.rgb()
    assert colour_at(image, view, -0.5, 1.6) == renderer.BACKGROUND.rgb()
    hit = QColor(renderer.HIT).rgb()
    assert any(QColor(image.pixel(c, r)).rgb() == hit for c in range(0, 800, 2) for r in range(0, 800, 2))


def test_save_png_writes_a_png(world, tmp_path):
    path = tmp_path / "view.png"
    save_png(scene_of(world, Trails()), path, 200, 150)
    image = QImage(str(path))
    assert (image.width(), image.height()) == (200, 150)
    assert path.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_unwritable_path_is_an_oserror(world, tmp_path):
    with pytest.raises(OSError, match="cannot write a PNG to"):
        save_png(scene_of(world, Trails()), tmp_path / "missing" / "view.png")
