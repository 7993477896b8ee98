"""turtlesim_node's ROS adapter (imports rospy): wires the TurtleSim core to topics, services
and parameters, and runs the 16 ms update timer with or without a window.

Graph (names relative to the node's namespace unless marked ~private), as the original:
* services clear, reset (std_srvs/Empty), spawn (turtlesim/Spawn), kill (turtlesim/Kill);
* per turtle (see ros/turtle.py): <name>/cmd_vel, <name>/pose, <name>/color_sensor,
  <name>/set_pen, <name>/teleport_absolute, <name>/teleport_relative;
* ~background_r, ~background_g, ~background_b (int, 69/86/255): written at start only when
  absent, read at start, clear and reset.
Added by the replica, off unless asked for, so `rosservice list` and `rosnode info` show the
original's graph:
* ~snapshot_service (bool, default false): true advertises ~snapshot (std_srvs/Empty), which
  saves the current view (trails and turtles) as PNG to ~snapshot_path (string, read at each
  call; default $ROS_HOME/turtlesim.png, ~ expanded). A path that cannot be written fails the
  call with a text naming it.
* ~publish_canvas (bool, default false): true publishes the pen canvas (trails only, no turtles)
  as sensor_msgs/CompressedImage PNG on ~canvas/compressed (image_transport's compressed name, so
  image_view shows it), latched, at most CANVAS_RATE_HZ while someone subscribes and only when it
  changed. lab_web's page draws the trails from it.
* ~headless (bool, default false): true never opens a window. Without it a 500x500 window
  titled TurtleSim opens when $DISPLAY names a reachable X server; ROS behaviour is identical.
Console lines are in roscpp's format (`[ INFO] [secs.nanosecs]: ...`, see ros/console.py).

Timing: every TICK_INTERVAL_MS of wall-clock time the core steps by its fixed DT; /use_sim_time
plays no part (the original's QTimer); when it is true and no /clock comes, the node says so once (sim_clock),
as the nodes that drive the turtle on rospy time would wait for ever. Service calls are answered at the start of
the next tick, before the turtles move, in the order they came (the original's spinOnce; see PendingCalls): a
/clear right after a teleport clears the teleport's line. cmd_vel callbacks hold the tick's lock, so each runs
entirely before or after a tick, never during one.
Failures reach clients as roscpp's do: `responded with an error: b''` for the original's
`return false`, the exception text for roscpp's InvalidNameException.
"""
import os
import threading
import time

import rospkg
import rospy
from std_srvs.srv import Empty, EmptyResponse
from window_hint import can_open_window

from master_reconnect import keep_registered
from roscpp_console.handler import use_roscpp_console
from sim_clock import warn_if_clock_missing
from stop_request import StopRequest
from stop_request.closed_topic import shutting_down
from turtlesim.core.constants import BACKGROUND_PARAMS, DEFAULT_BACKGROUND, TICK_INTERVAL_MS
from turtlesim.core.errors import InvalidNameError, TurtleSimError, UnknownTurtleError
from turtlesim.core.pending_calls import CallAbandoned, PendingCalls
from turtlesim.core.simulation import TurtleSim
from turtlesim.core.ticker import run_ticks
from turtlesim.ros.canvas import CanvasPublisher
from turtlesim.ros.log import ros_log
from turtlesim.ros.service import RoscppStyleService, ServiceFailure
from turtlesim.ros.turtle import TurtleInterfaces
from turtlesim.srv import (
    Kill,
    KillResponse,
    SetPenResponse,
    Spawn,
    SpawnResponse,
    TeleportAbsoluteResponse,
    TeleportRelativeResponse,
)
from turtlesim.view.scene_renderer import SceneRenderer
from turtlesim.view.window import run_window

NODE_NAME = 'turtlesim'

ROSCPP_EXCEPTION_LOG = 'Exception thrown while processing service call: %s'
"""roscpp's ERROR line when a service callback throws (the invalid spawn name case)."""

SNAPSHOT_FILE_NAME = 'turtlesim.png'
"""Default ~snapshot_path: this file in $ROS_HOME (~/.ros)."""


def read_private_param(name):
    """~name from the parameter server, or None when it is not set."""
    return rospy.get_param('~' + name, None)


def write_default_background():
    """Set ~background_r/g/b to the defaults where they are absent (the original's start-up)."""
    for name, default in zip(BACKGROUND_PARAMS, DEFAULT_BACKGROUND):
        if not rospy.has_param('~' + name):
            rospy.set_param('~' + name, default)


def failure_for(error):
    """Log a core TurtleSimError as the original does; return the ServiceFailure to raise."""
    if isinstance(error, InvalidNameError):
        rospy.logerr(ROSCPP_EXCEPTION_LOG % error)
    else:
        ros_log(error.level, str(error))
    return ServiceFailure('' if error.returns_false else str(error))


class TurtleSimNode:
    """One turtlesim node: the core, its ROS interfaces, the view, and the tick.

    Create it after rospy.init_node. `tick` is called by the timer (window or headless);
    `next_frame` by the window. Setting the `stop` event (e.g. from a signal handler) ends
    the timer loop.
    """

    def __init__(self, stop, snapshot_service=False, rng=None, publish_canvas=False):
        """Write default params, start the core (logs the start line and spawns turtle1),
        advertise turtle1's interfaces, then the global services (and ~snapshot if asked).

        Args:
            stop: a StopRequest; once set, `tick` returns False and `wait` returns True.
            snapshot_service: advertise ~snapshot too.
            publish_canvas: publish ~canvas/compressed too.
            rng: random.Random for the turtles' looks.
        """
        self._lock = threading.Lock()
        self._stop = stop
        self._pending = PendingCalls(lambda: stop.is_set() or rospy.is_shutdown())
        self._renderer = SceneRenderer()
        self._view_changed = True
        self._last_poses = []
        write_default_background()
        self._sim = TurtleSim(rospy.get_name(), read_private_param, ros_log, rng)
        self._turtles = {}
        self._sync_turtles()
        self._services = [
            RoscppStyleService('clear', Empty, self._on_clear),
            RoscppStyleService('reset', Empty, self._on_reset),
            RoscppStyleService('spawn', Spawn, self._on_spawn),
            RoscppStyleService('kill', Kill, self._on_kill),
        ]
        if snapshot_service:
            self._services.append(RoscppStyleService('~snapshot', Empty, self._on_snapshot))
        self._canvas = CanvasPublisher() if publish_canvas else None

    def tick(self):
        """One update: step the core at the current wall time, publish pose then color_sensor
        for every turtle. Returns False once a stop was requested or ROS shut down."""
        if self._stop.is_set() or rospy.is_shutdown():
            return False
        with self._lock:
            if self._pending.run_all():
                self._view_changed = True
            results = self._sim.step(time.time())
            try:
                for name, result in results:
                    self._turtles[name].publish(result)
            except rospy.ROSException:
                if shutting_down():
                    return False   # Ctrl-C closed the publishers after the shutdown check above
                raise
            if self._canvas is not None:
                self._canvas.publish_if_changed(self._sim.canvas, time.monotonic())
            poses = [(name, result.pose) for name, result in results]
            if poses != self._last_poses:
                self._last_poses = poses
                self._view_changed = True
        return True

    def next_frame(self):
        """The composed view (QImage) if anything visible changed since the last call, else None."""
        with self._lock:
            if not self._view_changed:
                return None
            self._view_changed = False
            return self._compose()

    def wait(self, seconds):
        """Sleep up to `seconds`; True as soon as a stop is requested."""
        return self._stop.wait(seconds)

    def on_cmd_vel(self, twist, name):
        """<name>/cmd_vel: linear.x, linear.y and angular.z, stamped with the wall time now."""
        now = time.time()
        with self._lock:
            try:
                self._sim.cmd_vel(name, twist.linear.x, twist.linear.y, twist.angular.z, now)
            except UnknownTurtleError as error:
                rospy.logdebug('cmd_vel arrived after its turtle was removed: %s', error)

    def set_pen(self, name, request):
        """<name>/set_pen: always succeeds while the turtle exists."""
        self._serve(self._sim.set_pen, name, request.r, request.g, request.b, request.width,
                    request.off)
        return SetPenResponse()

    def teleport_absolute(self, name, request):
        """<name>/teleport_absolute: queued for the next tick; non-finite values are ignored."""
        self._serve(self._sim.teleport_absolute, name, request.x, request.y, request.theta)
        return TeleportAbsoluteResponse()

    def teleport_relative(self, name, request):
        """<name>/teleport_relative: queued for the next tick; non-finite values are ignored."""
        self._serve(self._sim.teleport_relative, name, request.linear, request.angular)
        return TeleportRelativeResponse()

    def _on_clear(self, request):
        self._serve(self._sim.clear)
        return EmptyResponse()

    def _on_reset(self, request):
        self._serve(self._reset)
        return EmptyResponse()

    def _on_spawn(self, request):
        return SpawnResponse(self._serve(self._spawn, request))

    def _on_kill(self, request):
        self._serve(self._kill, request.name)
        return KillResponse()

    def _on_snapshot(self, request):
        path = snapshot_path()
        with self._lock:
            image = self._compose()
        if not image.save(path, 'PNG'):
            text = ('Could not write the snapshot to [%s]: the folder must exist and be '
                    'writable (set ~snapshot_path to change it)' % path)
            rospy.logerr(text)
            raise ServiceFailure(text)
        rospy.loginfo('Saved a snapshot of turtlesim to [%s]', path)
        return EmptyResponse()

    def _serve(self, action, *args):
        """Run one service action at the start of the next update, as the original's spinOnce does (see
        PendingCalls); core errors become ServiceFailure."""
        try:
            return self._pending.submit(action, *args)
        except TurtleSimError as error:
            raise failure_for(error) from None
        except CallAbandoned as error:
            raise ServiceFailure(str(error)) from None

    def _spawn(self, request):
        name = self._sim.spawn(request.name, request.x, request.y, request.theta)
        self._sync_turtles()
        return name

    def _kill(self, name):
        self._sim.kill(name)
        self._sync_turtles()

    def _reset(self):
        self._sim.reset()
        self._sync_turtles()

    def _sync_turtles(self):
        """Advertise the interfaces of new turtles, withdraw those of removed ones."""
        live = set(self._sim.names)
        for name in sorted(set(self._turtles) - live):
            self._turtles.pop(name).shutdown()
        for name in sorted(live - set(self._turtles)):
            self._turtles[name] = TurtleInterfaces(name, self)

    def _compose(self):
        return self._renderer.compose(self._sim.canvas,
                                      [turtle for _, turtle in self._sim.turtles()])


def snapshot_path():
    """~snapshot_path with ~ expanded; ServiceFailure when it is not a non-empty string."""
    default = os.path.join(rospkg.get_ros_home(), SNAPSHOT_FILE_NAME)
    path = rospy.get_param('~snapshot_path', default)
    if not isinstance(path, str) or not path:
        text = ('Parameter %s must be a file path (a non-empty string), got %r'
                % (rospy.resolve_name('~snapshot_path'), path))
        rospy.logerr(text)
        raise ServiceFailure(text)
    return os.path.expanduser(path)


def read_flag(name):
    """~name as a bool (default False); ValueError naming the parameter otherwise."""
    value = rospy.get_param('~' + name, False)
    if not isinstance(value, bool):
        raise ValueError('Parameter %s must be true or false, got %r'
                         % (rospy.resolve_name('~' + name), value))
    return value


def window_wanted(headless):
    """True when the window should open: not headless, and a display to open it on (or Qt was told to use another
    platform through QT_QPA_PLATFORM). Without one, one line says how to see the canvas here."""
    if headless:
        return False
    if os.environ.get('QT_QPA_PLATFORM'):
        return True
    return can_open_window('turtlesim', 'rosrun turtlesim turtlesim_node', rospy.loginfo, rospy.logwarn)


def main():
    """Run turtlesim_node until Ctrl-C, SIGTERM, rospy shutdown or the window closing."""
    stop = StopRequest()
    stop.install()
    rospy.init_node(NODE_NAME, disable_signals=True)
    use_roscpp_console()
    try:
        headless = read_flag('headless')
        snapshot_service = read_flag('snapshot_service')
        publish_canvas = read_flag('publish_canvas')
    except ValueError as error:
        rospy.logfatal(str(error))
        rospy.signal_shutdown(str(error))
        return 2
    with_window = window_wanted(headless)
    node = TurtleSimNode(stop, snapshot_service, publish_canvas=publish_canvas)
    keep_registered()
    warn_if_clock_missing()
    try:
        if with_window:
            run_window(node.tick, node.next_frame, rospy.myargv()[:1])
        else:
            run_ticks(node.tick, node.wait, TICK_INTERVAL_MS / 1000.0)
    finally:
        rospy.signal_shutdown('turtlesim closed')
    return 0
