"""Teleop from a page, made safe: the page repeats its command while a key is held, the server publishes at a
fixed rate while the commands keep coming, and sends zero once when they stop (key released, page closed,
network gone). No ROS import: the bridge calls `command`, `disconnect` and `tick` and publishes what they return.

Timing is wall time, not sim time: the page, the person and the network live in wall time, and a page that
vanished must stop the robot within half a second however fast the simulation runs.
"""
import threading

PUBLISH_RATE_HZ = 10.0
COMMAND_TIMEOUT_S = 0.3
"""No command for this long (the page sends one every 0.1 s while a key is held): zero and stop publishing."""

ROBOT_LIMITS = (0.26, 1.82)
"""TurtleBot3 Waffle's maximum linear (m/s) and angular (rad/s) velocity, as turtlebot3_teleop's."""
TURTLE_LIMITS = (2.0, 2.0)
"""turtle_teleop_key's steps for turtlesim (it sends exactly these)."""
TELEOP_LIMITS = {"robot": ROBOT_LIMITS, "turtle1": TURTLE_LIMITS}


class TeleopGate:
    """The command each target (robot, turtle1) should get now. Thread-safe: commands come from the web
    server's thread, ticks from the publishing thread."""

    def __init__(self):
        self._lock = threading.Lock()
        self._active = {}   # target -> (linear, angular, wall time of the command, owner)

    def command(self, owner, target, linear, angular, now_s):
        """A validated command from connection `owner`; the newest command for a target wins."""
        with self._lock:
            self._active[target] = (linear, angular, now_s, owner)

    def disconnect(self, owner, now_s):
        """`owner`'s page went away: its targets get zero at the next tick."""
        with self._lock:
            for target, (_, _, _, command_owner) in list(self._active.items()):
                if command_owner == owner:
                    self._active[target] = (0.0, 0.0, now_s - COMMAND_TIMEOUT_S, owner)

    def stop_all(self, now_s):
        """Every driven target gets zero at the next tick (the server is shutting down, another robot is picked)."""
        with self._lock:
            for target, (_, _, _, owner) in list(self._active.items()):
                self._active[target] = (0.0, 0.0, now_s - COMMAND_TIMEOUT_S, owner)

    def tick(self, now_s):
        """[(target, linear, angular)] to publish now: the held commands, and a final zero for each target whose
        commands stopped (released to zero, timed out or disconnected); nothing while no page drives."""
        out = []
        with self._lock:
            for target, (linear, angular, stamp, _) in list(self._active.items()):
                if now_s - stamp >= COMMAND_TIMEOUT_S or (linear == 0.0 and angular == 0.0):
                    del self._active[target]
                    out.append((target, 0.0, 0.0))
                else:
                    out.append((target, linear, angular))
        return out
