"""Named constants of the original turtlesim (ros/ros_tutorials noetic-devel, 0.10.2).

Units are in the names or docstrings. World frame: origin bottom-left, x right, y up, metres,
theta in radians counter-clockwise from +x. Screen frame: origin top-left, x right, y down,
metres; pixels = screen metres x PIXELS_PER_METRE.
"""
import numpy

CANVAS_SIZE_PX = 500
"""Width and height of the square window and pen canvas, in pixels."""

PIXELS_PER_METRE = 45.0
"""Height of the original's first turtle image (box-turtle.png); it sets the scale."""

WORLD_SIZE = float(numpy.float32((CANVAS_SIZE_PX - 1) / PIXELS_PER_METRE))
"""World width and height in metres: (500 - 1) / 45 rounded to float32, 11.088889122009277."""

WORLD_CENTRE = float(numpy.float32(WORLD_SIZE / 2.0))
"""Start x and y of turtle1 in metres (float32 5.544444561004639, logged as 5.544445)."""

TICK_INTERVAL_MS = 16
"""Period of the update timer in wall-clock milliseconds (a QTimer in the original)."""

DT = 0.016
"""Fixed simulation step in seconds (0.001 x the 16 ms Qt timer); elapsed time is never used."""

WINDOW_TITLE = 'TurtleSim'
"""Title of the fixed-size CANVAS_SIZE_PX x CANVAS_SIZE_PX window."""

PI = 3.14159265
"""The original's PI macro, used in the heading wrap and the sprite rotation (not math.pi)."""

CMD_TIMEOUT = 1.0
"""Seconds of wall time after the last cmd_vel before a turtle's velocities are zeroed."""

DEFAULT_BACKGROUND = (69, 86, 255)
"""Background RGB (0x45, 0x56, 0xff) used when ~background_r/g/b are missing or not numbers."""

BACKGROUND_PARAMS = ('background_r', 'background_g', 'background_b')
"""Private parameter names of the background channels, in DEFAULT_BACKGROUND order."""

DEFAULT_PEN_COLOUR = (179, 184, 255)
"""Pen RGB (0xb3, 0xb8, 0xff) of a new turtle."""

DEFAULT_PEN_WIDTH = 3
"""Pen width in pixels of a new turtle."""

TURTLE_IMAGE_COUNT = 14
"""Number of turtle looks; the original picks one of 14 images uniformly at random."""

AUTO_NAME_PREFIX = 'turtle'
"""Auto-names are this prefix followed by the counter: turtle1, turtle2, ..."""
