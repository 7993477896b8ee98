"""One turtle: pose, commanded velocity, pen and queued teleports; the original's Turtle::update.

The state is kept like the original's: position in screen metres (x right, y down) as doubles,
heading in radians as a double, velocities as doubles. Published values are rounded to float32.
All inputs must be finite; TurtleSim rejects NaN and infinities before they get here.
"""
import math
from typing import NamedTuple, Optional, Tuple

import numpy

from turtlesim.core.constants import CMD_TIMEOUT, WORLD_SIZE
from turtlesim.core.geometry import Pose, as_float32, qt_fuzzy_equal, wrap_heading
from turtlesim.core.pen import DEFAULT_PEN, Pen

WALL_WARNING = 'Oh no! I hit the wall! (Clamping from [x=%f, y=%f])'
"""ROS_WARN text of a wall hit, formatted with the pre-clamp x and the screen-space y."""


class TeleportAbsolute(NamedTuple):
    """teleport_absolute request: world x, y in metres and theta in radians (float32 values)."""

    x: float
    y: float
    theta: float


class TeleportRelative(NamedTuple):
    """teleport_relative request: turn by `angular` rad first, then move `linear` metres."""

    linear: float
    angular: float


class TickResult(NamedTuple):
    """What one update produced: the pose and color_sensor to publish, and the wall warning
    text (None when the turtle stayed inside) to log at WARN level."""

    pose: Pose
    color: Tuple[int, int, int]
    wall_warning: Optional[str]


class Turtle:
    """A turtle of the original turtlesim.

    Quirks kept on purpose: holonomic motion (vy strafes), heading updated before position,
    wrap with PI = 3.14159265, wall warning with screen-space y, velocities not zeroed at walls,
    linear_velocity reported as a magnitude, teleport y above the top clamped silently.
    """

    def __init__(self, x, y, theta, image_index=0):
        """Place a stopped turtle with the default pen, pen on.

        Args:
            x, y: world metres, theta: radians (the spawn request's float32 values). The screen
                y is computed in float32 (WORLD_SIZE - y), as the original does.
            image_index: which of the TURTLE_IMAGE_COUNT looks the renderer draws (cosmetic).
        """
        with numpy.errstate(over='ignore'):
            y_screen = numpy.float32(WORLD_SIZE) - numpy.float32(y)
        self._x = as_float32(x)
        self._y = float(y_screen)
        self._theta = as_float32(theta)
        self._vx = 0.0
        self._vy = 0.0
        self._w = 0.0
        self._last_command_time = 0.0
        self._pen = DEFAULT_PEN
        self._pen_on = True
        self._teleports = []
        self.image_index = image_index

    @property
    def screen_position(self):
        """(x, y) in screen metres (y down), as last updated."""
        return self._x, self._y

    @property
    def heading(self):
        """Heading in radians, counter-clockwise from +x (wrapped at each update)."""
        return self._theta

    @property
    def pen(self):
        """The current Pen (kept while the pen is off)."""
        return self._pen

    @property
    def pen_on(self):
        """True when motion and teleports draw."""
        return self._pen_on

    def set_command(self, vx, vy, w, now):
        """Take a cmd_vel: linear.x and linear.y in m/s (turtle frame), angular.z in rad/s.

        `now` is wall-clock seconds; the command lasts until CMD_TIMEOUT after it.
        """
        self._vx, self._vy, self._w = vx, vy, w
        self._last_command_time = now

    def set_pen(self, r, g, b, width, off):
        """The set_pen service: off != 0 only lifts the pen (colour and width kept); otherwise
        the pen goes down with a new Pen((r, g, b), width); width 0 means Qt's default 1 px."""
        self._pen_on = not off
        if not off:
            self._pen = Pen((r, g, b), width)

    def queue_teleport(self, request):
        """Queue a TeleportAbsolute or TeleportRelative; applied in order at the next update."""
        self._teleports.append(request)

    def update(self, dt, now, canvas):
        """Advance one tick of `dt` seconds at wall time `now`; draw pen lines on `canvas`.

        Steps (spec 1.7 a-g): apply queued teleports (each drawing a line when the pen is on);
        zero the velocities if more than CMD_TIMEOUT passed since the last command; turn, wrap,
        then move along the new heading; clamp to the walls; build the pose; sample the canvas
        colour under the turtle; draw this tick's pen segment if the position changed.
        """
        self._apply_teleports(canvas)
        if now - self._last_command_time > CMD_TIMEOUT:
            self._vx = self._vy = self._w = 0.0
        old_position = (self._x, self._y)
        self._theta = wrap_heading(self._theta + self._w * dt)
        cos_theta, sin_theta = math.cos(self._theta), math.sin(self._theta)
        self._x += cos_theta * self._vx * dt - sin_theta * self._vy * dt
        self._y -= cos_theta * self._vy * dt + sin_theta * self._vx * dt
        wall_warning = self._clamp_to_walls()
        pose = Pose(x=as_float32(self._x),
                    y=as_float32(WORLD_SIZE - self._y),
                    theta=as_float32(self._theta),
                    linear_velocity=as_float32(math.sqrt(self._vx * self._vx
                                                         + self._vy * self._vy)),
                    angular_velocity=as_float32(self._w))
        color = canvas.color_at((self._x, self._y))
        if self._pen_on and not (qt_fuzzy_equal(self._x, old_position[0])
                                 and qt_fuzzy_equal(self._y, old_position[1])):
            canvas.draw_line((self._x, self._y), old_position, self._pen)
        return TickResult(pose, color, wall_warning)

    def _apply_teleports(self, canvas):
        for request in self._teleports:
            old_position = (self._x, self._y)
            if isinstance(request, TeleportRelative):
                self._theta += request.angular
                self._x += math.cos(self._theta) * request.linear
                self._y += -math.sin(self._theta) * request.linear
            else:
                self._x = request.x
                self._y = max(0.0, WORLD_SIZE - request.y)
                self._theta = request.theta
            if self._pen_on:
                canvas.draw_line((self._x, self._y), old_position, self._pen)
        self._teleports.clear()

    def _clamp_to_walls(self):
        warning = None
        if not (0.0 <= self._x <= WORLD_SIZE and 0.0 <= self._y <= WORLD_SIZE):
            warning = WALL_WARNING % (self._x, self._y)
        self._x = min(max(self._x, 0.0), WORLD_SIZE)
        self._y = min(max(self._y, 0.0), WORLD_SIZE)
        return warning
