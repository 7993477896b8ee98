"""`roslaunch com2009_simulations <task>.launch` for every world of the package: the original's model names and
the robot at the launch file's spawn defaults in /gazebo/model_states, and /scan reading the original's walls,
pillars and beacons (2 cm).

Expected ranges come from the original's SDF numbers (roslab.scan_geometry), not from the lab's world files.
Each launch runs on a master of its own at 10x real time (conftest.py)."""
from roslab.scan_geometry import Disc, Rect

from .world_checks import (  # noqa: F401  (the shared tests run against this module's CASES)
    FloorView,
    WorldCase,
    test_camera_shows_the_floor_art_where_the_projection_puts_it,
    test_models_are_the_originals_and_the_robot_stands_at_the_spawn_pose,
    test_scan_reads_the_originals_walls_and_pillars,
)

CR5_WALLS = (   # cr5_arena_walls: 0.16 m tall, inner faces at +-1.92
    Rect((0.0, 1.96), (3.84, 0.08)), Rect((-1.96, 0.0), (0.08, 4.0)),
    Rect((0.0, -1.96), (3.84, 0.08)), Rect((1.96, 0.0), (0.08, 4.0)))
ARENA_WALLS = (   # arena_walls (the mazes): 4.9 x 0.1 boxes in a pinwheel, inner faces at +-2.40
    Rect((0.05, 2.45), (4.9, 0.1)), Rect((-2.45, 0.05), (4.9, 0.1), 1.5708),
    Rect((-0.05, -2.45), (4.9, 0.1)), Rect((2.45, -0.05), (4.9, 0.1), 1.5708))
TASK1_PILLARS = (Disc((-0.5, 0.0), 0.1), Disc((0.5, 0.0), 0.1))
TASK2_PILLARS = (Disc((-0.78, 0.0), 0.1), Disc((0.0, 0.78), 0.1), Disc((0.0, -0.78), 0.1), Disc((0.78, 0.0), 0.1))
TASK3_START_ZONE = (   # the blue U round maze A's spawn, and Wall_03 across the corridor ahead
    Rect((-2.373, -2.095), (0.57, 0.03), 1.5708), Rect((-2.073, -2.365), (0.57, 0.03)),
    Rect((-1.803, -2.080), (0.54, 0.03), 1.5708), Rect((-2.085, -0.541), (0.6, 0.03)))
TASK3B_START_ZONE = (   # the blue U round maze B's spawn, and wall_1 ahead
    Rect((0.293, -2.371), (0.57, 0.03), -3.1412), Rect((0.563, -2.071), (0.57, 0.03), -1.5702),
    Rect((0.278, -1.801), (0.54, 0.03), -3.1412), Rect((-1.191, -1.791), (0.03, 1.2)))
TASK4_ROOM_WALLS = (   # room_1.long_1 and room_2.long_2, next to the spawn
    Rect((1.480, -0.566), (0.88, 0.01)), Rect((0.674, 0.397), (0.88, 0.01)))
EVERY_QUARTER = (0.0, 90.0, 180.0, 270.0)
WHITE, BLACK, ZONE_PINK = (255, 255, 255), (0, 0, 0), (255, 128, 128)

CASES = [
    WorldCase("com2009_simulations", "empty_arena.launch", ("gui:=false",), (0.0, 0.0, 0.0),
              ("cr5_arena_floor", "cr5_arena_walls"), EVERY_QUARTER, CR5_WALLS,
              (FloorView((0.0, 0.0, 0.0), (0.4, 0.0), WHITE),)),
    WorldCase("com2009_simulations", "task1.launch", ("gui:=false",), (0.0, 0.0, -1.571),
              ("obstacle_avoidance", "cr5_arena_walls"), EVERY_QUARTER, CR5_WALLS + TASK1_PILLARS,
              (FloorView((0.0, 0.0, -1.571), (-0.047, -0.45), WHITE),)),
    WorldCase("com2009_simulations", "task2.launch", ("gui:=false",), (0.0, 0.0, -3.142),
              ("task2", "cr5_arena_walls"), (0.0, 15.0, 90.0, 105.0, 180.0, 270.0), CR5_WALLS + TASK2_PILLARS,
              (FloorView((0.0, 0.0, -3.142), (-0.6, -0.15), ZONE_PINK),)),   # the central zone beside START
    WorldCase("com2009_simulations", "task3.launch", ("gui:=false",), (-2.088, -2.027, 1.572),
              ("arena_walls", "task3_maze"), (0.0, 90.0, 120.0, 180.0, 270.0), ARENA_WALLS + TASK3_START_ZONE,
              (FloorView((-2.088, -2.027, 1.572), (-2.0, -1.4), WHITE),)),
    WorldCase("com2009_simulations", "task3b.launch", ("gui:=false",), (0.233, -2.08583, 3.142),
              ("arena_walls", "task3b"), (0.0, 90.0, 180.0, 210.0, 270.0), ARENA_WALLS + TASK3B_START_ZONE,
              (FloorView((0.233, -2.08583, 3.142), (-0.05, -2.086), BLACK),)),   # START's middle arrow
    WorldCase("com2009_simulations", "task4.launch", ("gui:=false",), (1.42, 0.0, -3.142),
              ("task4_explore", "cr5_arena_walls"), (0.0, 90.0, 135.0, 270.0), CR5_WALLS + TASK4_ROOM_WALLS,
              (FloorView((1.42, 0.0, -3.142), (1.0, 0.0), WHITE),)),
]
