"""TurtleSim: the original's TurtleFrame without Qt widgets or ROS — turtles, canvas, services.

Contract for the ROS adapter:
* Calls must be serialised: the original runs every callback and the update on one thread,
  callbacks first (ros::spinOnce) then `step`. The class is not thread-safe.
* Log lines go to the `log` sink as (LogLevel, text), in the original's order and wording.
* Failures raise a TurtleSimError subclass carrying the text to log and how the original
  fails (see errors.py); nothing is logged for them by the core and no state changes.
* Requests are the services' float32 values; they are rounded to float32 here too, so direct
  callers get the same arithmetic. NaN/inf (or float32 overflow) never reach a turtle: cmd_vel
  and teleports are ignored with a WARN line (those services cannot fail in the original), and
  spawn raises NonFiniteValueError (there is no name to return).
"""
import math
import random

from turtlesim.core.background import read_background
from turtlesim.core.canvas import Canvas
from turtlesim.core.constants import AUTO_NAME_PREFIX, DT, TURTLE_IMAGE_COUNT, WORLD_CENTRE
from turtlesim.core.errors import DuplicateNameError, NonFiniteValueError, UnknownTurtleError
from turtlesim.core.geometry import all_finite, as_float32
from turtlesim.core.log import LogLevel
from turtlesim.core.names import validate_name
from turtlesim.core.turtle import TeleportAbsolute, TeleportRelative, Turtle

NON_FINITE_TEXT = ('Ignoring %s for turtle [%s]: %s are not all finite; '
                   'only finite numbers are allowed')


class TurtleSim:
    """All turtles of one turtlesim node, the pen canvas and the auto-name counter."""

    def __init__(self, node_name, read_param, log, rng=None):
        """Fill the canvas from the background params, log the start line, spawn turtle1.

        Args:
            node_name: fully resolved node name, only for the start log line.
            read_param: callable(name) -> value or None; reads the private background_r/g/b
                parameters at start, clear and reset (see background.read_background).
            log: LogSink, callable(LogLevel, text).
            rng: random.Random choosing each turtle's look (seed it for repeatable looks).
        """
        self._read_param = read_param
        self._log = log
        self._rng = rng if rng is not None else random.Random()
        self._canvas = Canvas(read_background(read_param))
        self._turtles = {}
        self._auto_name_counter = 0
        self._started = False
        self._log(LogLevel.INFO, 'Starting turtlesim with node name %s' % node_name)
        self._spawn_turtle('', WORLD_CENTRE, WORLD_CENTRE, 0.0)

    @property
    def canvas(self):
        """The pen Canvas (trails only)."""
        return self._canvas

    @property
    def names(self):
        """Names of the live turtles, in update order (std::map: sorted by code point)."""
        return sorted(self._turtles)

    def turtles(self):
        """(name, Turtle) pairs in update order; the renderer draws them in this order."""
        return [(name, self._turtles[name]) for name in self.names]

    def step(self, now):
        """One 16 ms tick at wall time `now` (seconds): update every turtle by DT.

        Returns [(name, TickResult)] in update order, to publish pose then color_sensor per
        turtle. Wall warnings are logged at WARN. The very first call only marks the start
        and returns [] (the original records a timestamp and updates nothing).
        """
        if not self._started:
            self._started = True
            return []
        results = []
        for name in self.names:
            result = self._turtles[name].update(DT, now, self._canvas)
            if result.wall_warning is not None:
                self._log(LogLevel.WARN, result.wall_warning)
            results.append((name, result))
        return results

    def spawn(self, name, x, y, theta):
        """The spawn service: world x, y (metres), theta (rad); '' asks for an auto-name.

        Returns the new turtle's name. Raises NonFiniteValueError, DuplicateNameError or
        InvalidNameError (roscpp's text). Auto-naming: the counter is incremented, then
        'turtle<N>' is tried, repeating while that name exists; explicit names leave it alone.
        """
        x, y, theta = as_float32(x), as_float32(y), as_float32(theta)
        if not all_finite(x, y, theta):
            raise NonFiniteValueError(NON_FINITE_TEXT % ('spawn', name, 'x, y, theta'))
        return self._spawn_turtle(name, x, y, theta)

    def kill(self, name):
        """The kill service: remove the turtle; its trail stays. Raises UnknownTurtleError."""
        if name not in self._turtles:
            raise UnknownTurtleError(
                'Tried to kill turtle [%s], which does not exist' % name)
        del self._turtles[name]

    def clear(self):
        """The clear service: re-read the background params and erase all trails."""
        self._log(LogLevel.INFO, 'Clearing turtlesim.')
        self._fill_background()

    def reset(self):
        """The reset service: remove all turtles, rewind the auto-name counter to 0, spawn a
        new auto-named turtle (turtle1) at the centre, then clear. Returns the new name."""
        self._log(LogLevel.INFO, 'Resetting turtlesim.')
        self._turtles.clear()
        self._auto_name_counter = 0
        name = self._spawn_turtle('', WORLD_CENTRE, WORLD_CENTRE, 0.0)
        self._fill_background()
        return name

    def set_pen(self, name, r, g, b, width, off):
        """The set_pen service (uint8 fields); see Turtle.set_pen. Raises UnknownTurtleError."""
        self._turtle(name).set_pen(r, g, b, width, off)

    def teleport_absolute(self, name, x, y, theta):
        """Queue a teleport to world (x, y, theta) for the turtle's next update.

        y above the top becomes the top edge silently; x and y below 0 are clamped (with the
        wall warning) by that update. Non-finite values: WARN logged, request ignored.
        """
        turtle = self._turtle(name)
        request = TeleportAbsolute(as_float32(x), as_float32(y), as_float32(theta))
        if not all_finite(*request):
            self._log(LogLevel.WARN,
                      NON_FINITE_TEXT % ('teleport_absolute', name, 'x, y, theta'))
            return
        turtle.queue_teleport(request)

    def teleport_relative(self, name, linear, angular):
        """Queue a relative teleport: turn by `angular` rad, then move `linear` metres.

        Non-finite values: WARN logged, request ignored.
        """
        turtle = self._turtle(name)
        request = TeleportRelative(as_float32(linear), as_float32(angular))
        if not all_finite(*request):
            self._log(LogLevel.WARN,
                      NON_FINITE_TEXT % ('teleport_relative', name, 'linear, angular'))
            return
        turtle.queue_teleport(request)

    def cmd_vel(self, name, vx, vy, w, now):
        """A Twist on <name>/cmd_vel: linear.x, linear.y (m/s), angular.z (rad/s) at wall time
        `now` (s). Non-finite values: WARN logged, message ignored (the previous command and
        its timeout stay). So are values, or a speed magnitude, beyond float32 (|v| > 3.4e38):
        the published float32 pose would carry inf where the original publishes it (found by
        fuzzing). Raises UnknownTurtleError for a name that does not exist."""
        turtle = self._turtle(name)
        if not all_finite(as_float32(vx), as_float32(vy), as_float32(w),
                          as_float32(math.hypot(vx, vy))):
            self._log(LogLevel.WARN,
                      NON_FINITE_TEXT % ('cmd_vel', name, 'linear.x, linear.y, angular.z'))
            return
        turtle.set_command(vx, vy, w, now)

    def _turtle(self, name):
        try:
            return self._turtles[name]
        except KeyError:
            raise UnknownTurtleError('No turtle named [%s]' % name) from None

    def _spawn_turtle(self, name, x, y, theta):
        if not name:
            name = self._next_auto_name()
        elif name in self._turtles:
            raise DuplicateNameError(name)
        else:
            validate_name(name)
        image_index = self._rng.randrange(TURTLE_IMAGE_COUNT)
        self._turtles[name] = Turtle(x, y, theta, image_index)
        self._log(LogLevel.INFO, 'Spawning turtle [%s] at x=[%f], y=[%f], theta=[%f]'
                  % (name, x, y, theta))
        return name

    def _next_auto_name(self):
        while True:
            self._auto_name_counter += 1
            name = '%s%d' % (AUTO_NAME_PREFIX, self._auto_name_counter)
            if name not in self._turtles:
                return name

    def _fill_background(self):
        self._canvas.clear(read_background(self._read_param))
