"""`roslaunch tuos_simulations <world>.launch` for every world of the package: the original's model names and the
robot at the launch file's spawn defaults (and at x_pos/y_pos/yaw given on the command line) in
/gazebo/model_states, /scan reading the original's walls and pillars (2 cm) or nothing where the world has none,
mystery_world headless by default with camera_search:=true starting the CameraSweep action server,
roslaunch refusing to start while TURTLEBOT3_MODEL is unset, as the original's bare $(env) does, and rviz.launch
starting robot_state_publisher (50 Hz) and rviz (node tb3_rviz) for the model.

Expected ranges come from the original's SDF numbers (roslab.scan_geometry), not from the lab's world files.
Each launch runs on a master of its own at 10x real time (conftest.py)."""
import os
import subprocess

import rosgraph
import roslaunch.config
import roslaunch.node_args
import roslaunch.rlutil

from roslab import wait_for_topic
from roslab.scan_geometry import Disc, Rect

from .world_checks import (  # noqa: F401  (the shared tests run against this module's CASES)
    FloorView,
    WorldCase,
    test_camera_shows_the_floor_art_where_the_projection_puts_it,
    test_models_are_the_originals_and_the_robot_stands_at_the_spawn_pose,
    test_scan_reads_the_originals_walls_and_pillars,
)

ARENA_WALLS = (   # tuos arena_walls: 4.9 x 0.1 boxes in a pinwheel, inner faces at +-2.40
    Rect((0.05, 2.45), (4.9, 0.1)), Rect((-2.45, 0.05), (4.9, 0.1), 1.5708),
    Rect((-0.05, -2.45), (4.9, 0.1)), Rect((2.45, -0.05), (4.9, 0.1), 1.5708))
NAVIGATION_WALLS = (   # navigation's wall_4, wall_6, wall_7 (0.03 x 1.05), the walls the spawn faces
    Rect((0.0, -0.041), (0.03, 1.05)), Rect((1.276, -1.072), (0.03, 1.05)), Rect((0.696, -1.582), (1.05, 0.03)))
SQUARE_AND_PILLARS = (   # turtlebot3_square (4 x 0.15 boxes, inner faces +-1.85) and obstacle's 4 cylinders
    Rect((0.0, 1.925), (4.0, 0.15)), Rect((-1.925, 0.0), (4.0, 0.15), -1.5708),
    Rect((0.0, -1.925), (4.0, 0.15)), Rect((1.925, 0.0), (4.0, 0.15), 1.5708),
    Disc((-0.6, -0.6), 0.15), Disc((-0.6, 0.6), 0.15), Disc((0.6, -0.6), 0.15), Disc((0.6, 0.6), 0.15))
PILLARS_MODELS = ("ground_plane", "turtlebot3_square", "obstacle")
EVERY_QUARTER = (0.0, 90.0, 180.0, 270.0)
CAMERA_SWEEP_RESULT = "/camera_sweep_action_server/result"
PINK, YELLOW, GREEN = (255, 0, 255), (255, 255, 0), (0, 255, 0)
START_GREY = (0xcd, 0xcd, 0xcd)
NAV_VIEWS = (
    FloorView((-1.853, -1.608, -1.5708), (-1.900, -1.977), GREEN),   # inside zone A, looking at its disc
    FloorView((0.409, -0.6, 1.5708), (0.456, -0.2), START_GREY))    # the START square, from its -y side

CASES = [
    WorldCase("tuos_simulations", "nav_world.launch", ("gui:=false",), (0.5, -0.04, 0.0),
              ("navigation", "arena_walls"), (0.0, 90.0, 180.0, 270.0, 315.0), ARENA_WALLS + NAVIGATION_WALLS,
              NAV_VIEWS),
    WorldCase("tuos_simulations", "line_following_setup.launch", ("gui:=false",), (0.5, -5.48, 1.57),
              ("line_following_setup",), EVERY_QUARTER, (),
              (FloorView((0.5, -5.48, 1.57), (0.0, -4.5), PINK), FloorView((0.5, -5.48, 1.57), (0.5, -5.0), YELLOW))),
    WorldCase("tuos_simulations", "line_following.launch", ("gui:=false",), (2.4, -2.5, 3.14),
              ("line_following_track",), EVERY_QUARTER, (), (FloorView((2.4, -2.5, 3.14), (1.88, -2.56), PINK),)),
    WorldCase("tuos_simulations", "line_following.launch", ("gui:=false", "x_pos:=3", "y_pos:=-3", "yaw:=0"),
              (3.0, -3.0, 0.0), ("line_following_track",), EVERY_QUARTER, (),
              (FloorView((3.0, -3.0, 0.0), (3.4, -3.0), YELLOW),)),   # yellow floor; no line in view
    WorldCase("tuos_simulations", "coloured_pillars.launch", ("gui:=false",), (0.0, 0.0, 0.0), PILLARS_MODELS,
              (0.0, 45.0, 90.0, 135.0, 180.0, 225.0, 270.0, 315.0), SQUARE_AND_PILLARS),
    # No gui argument: the original's default runs Gazebo headless.
    WorldCase("tuos_simulations", "mystery_world.launch", ("camera_search:=true",), (0.0, 0.0, 0.0), PILLARS_MODELS,
              (0.0, 45.0, 90.0, 180.0, 270.0), SQUARE_AND_PILLARS),
]


def test_simulator_is_headless_and_camera_search_starts_the_sweep_server(case, case_master, world):
    assert rosgraph.Master("/test", master_uri=case_master.uri).getParam("/gazebo/headless") is True
    if "camera_search:=true" in case.args:
        wait_for_topic(case_master.uri, CAMERA_SWEEP_RESULT, timeout_s=30)


def test_roslaunch_refuses_to_start_without_turtlebot3_model():
    """`roslaunch --nodes tuos_simulations nav_world.launch` (parse only, no master) with TURTLEBOT3_MODEL unset."""
    environment = {k: v for k, v in os.environ.items() if k != "TURTLEBOT3_MODEL"}
    finished = subprocess.run(["roslaunch", "--nodes", "tuos_simulations", "nav_world.launch"], env=environment,
                              stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, timeout=60)
    assert finished.returncode != 0
    assert "environment variable 'TURTLEBOT3_MODEL' is not set" in finished.stdout


def test_rviz_launch_runs_robot_state_publisher_at_50_hz_and_rviz_for_the_model(monkeypatch):
    """What rviz.launch starts, as `roslaunch --nodes` and `--dump-params` read it (roslaunch's own loader, in this
    process: two roslaunch starts cost 3 CPU s; the command line itself is under test above). rviz itself under a
    virtual display is turtlebot3_description's test_model_launch, with the same rviz and model.rviz."""
    monkeypatch.setenv("TURTLEBOT3_MODEL", "burger")
    config = roslaunch.config.load_config_default(
        roslaunch.rlutil.resolve_launch_arguments(["tuos_simulations", "rviz.launch"]), None)
    assert roslaunch.node_args.get_node_list(config) == ["/robot_state_publisher", "/tb3_rviz"]
    assert config.params["/robot_state_publisher/publish_frequency"].value == 50.0
    assert '<robot name="turtlebot3_burger"' in config.params["/robot_description"].value
