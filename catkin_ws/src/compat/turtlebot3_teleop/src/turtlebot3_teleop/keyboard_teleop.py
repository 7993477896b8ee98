"""What turtlebot3_teleop_key (ROBOTIS turtlebot3, noetic) does with each key: no ROS, no terminal.

Keys (one character each):
    w / x      target linear velocity +/- LINEAR_STEP_MPS (0.01 m/s)
    a / d      target angular velocity +/- ANGULAR_STEP_RADPS (0.1 rad/s)
    s, space   force stop: targets and the ramped command drop to 0 at once
    Ctrl-C     quit (QUIT_KEY, '\\x03': the terminal is raw, so Ctrl-C arrives as a character)
    anything else, or no key within the read timeout: ignored (the ramp still advances)

Targets are clamped to the model's limits (MODEL_LIMITS). The command actually sent moves towards the
target by half a step per loop (0.005 m/s, 0.05 rad/s) and never overshoots it. The node runs one loop per
key read, so once per key, or every read timeout (0.1 s) while no key comes.

Printed text: BANNER at start; after every w/x/a/d and stop key a status line (`status_line`) with the
*targets*; the banner again after every STATUS_LINES_PER_BANNER w/x/a/d presses (stop keys do not count).

Quirks of the original kept on purpose:
- the status line shows the accumulated floats as Python prints them, e.g. `0.060000000000000005` after six
  presses of w, and ends with a space;
- a model the original does not know (including the burger default) gets the burger's limits;
- a w/x/a/d press that the limit clamps still prints a status line and counts towards the banner.
"""
from dataclasses import dataclass

LINEAR_STEP_MPS = 0.01
"""Change of the target linear velocity per w/x press [m/s]."""

ANGULAR_STEP_RADPS = 0.1
"""Change of the target angular velocity per a/d press [rad/s]."""

LINEAR_RAMP_MPS = LINEAR_STEP_MPS / 2.0
"""Largest change of the linear command per loop [m/s]: half a step."""

ANGULAR_RAMP_RADPS = ANGULAR_STEP_RADPS / 2.0
"""Largest change of the angular command per loop [rad/s]: half a step."""

QUIT_KEY = "\x03"
"""Ctrl-C as the raw terminal delivers it."""

STOP_KEYS = frozenset({"s", " "})

KEY_STEPS = {
    "w": (LINEAR_STEP_MPS, 0.0),
    "x": (-LINEAR_STEP_MPS, 0.0),
    "a": (0.0, ANGULAR_STEP_RADPS),
    "d": (0.0, -ANGULAR_STEP_RADPS),
}
"""Key -> (linear change [m/s], angular change [rad/s]) of the targets."""

STATUS_LINES_PER_BANNER = 20
"""The banner is printed again after this many w/x/a/d presses."""

BANNER = """
Control Your TurtleBot3!
---------------------------
Moving around:
        w
   a    s    d
        x

w/x : increase/decrease linear velocity (Burger : ~ 0.22, Waffle and Waffle Pi : ~ 0.26)
a/d : increase/decrease angular velocity (Burger : ~ 2.84, Waffle and Waffle Pi : ~ 1.82)

space key, s : force stop

CTRL-C to quit
"""
"""The instructions, printed (as one print, so followed by an empty line) at start and every
STATUS_LINES_PER_BANNER presses."""


@dataclass(frozen=True)
class VelocityLimits:
    """Largest magnitude of the target velocities: linear [m/s], angular [rad/s]."""

    linear_mps: float
    angular_radps: float


MODEL_LIMITS = {
    "burger": VelocityLimits(linear_mps=0.22, angular_radps=2.84),
    "waffle": VelocityLimits(linear_mps=0.26, angular_radps=1.82),
    "waffle_pi": VelocityLimits(linear_mps=0.26, angular_radps=1.82),
}
"""TurtleBot3 model name (the `model` parameter) -> its limits."""

DEFAULT_MODEL = "burger"
"""The model when the `model` parameter is not set (the launch file always sets it)."""


def is_known_model(model):
    """True when `model` is a name in MODEL_LIMITS."""
    return isinstance(model, str) and model in MODEL_LIMITS


def limits_for_model(model):
    """The VelocityLimits of `model`; the burger's for any other value, as the original does."""
    return MODEL_LIMITS[model] if is_known_model(model) else MODEL_LIMITS["burger"]


def clamp(value, limit):
    """`value` limited to [-limit, limit]."""
    return max(-limit, min(limit, value))


def ramp(current, target, max_change):
    """One loop of the original's velocity profile: `current` moved towards `target` by at most
    `max_change`, never past it."""
    if target > current:
        return min(target, current + max_change)
    if target < current:
        return max(target, current - max_change)
    return target


def status_line(linear_mps, angular_radps):
    """The line printed after a velocity key, with both values as Python prints floats."""
    return "currently:\tlinear vel {}\t angular vel {} ".format(linear_mps, angular_radps)


def is_quit(key):
    """True for the key that ends the teleop (Ctrl-C)."""
    return key == QUIT_KEY


class KeyboardTeleop:
    """The teleop's state: target velocities set by keys and the ramped command sent to the robot.

    Per loop the node calls `press(key)` (key None when none came), prints the lines it returns, then sends
    the (linear [m/s], angular [rad/s]) that `step()` returns.
    """

    def __init__(self, limits=MODEL_LIMITS[DEFAULT_MODEL]):
        self.limits = limits
        self.target_linear_mps = 0.0
        self.target_angular_radps = 0.0
        self.linear_mps = 0.0
        self.angular_radps = 0.0
        self._presses_since_banner = 0

    def press(self, key):
        """Apply one key (a one-character str, or None) to the targets; returns the lines to print."""
        if key in KEY_STEPS:
            linear_change, angular_change = KEY_STEPS[key]
            self.target_linear_mps = clamp(self.target_linear_mps + linear_change, self.limits.linear_mps)
            self.target_angular_radps = clamp(self.target_angular_radps + angular_change, self.limits.angular_radps)
            self._presses_since_banner += 1
        elif key in STOP_KEYS:
            self.stop()
        else:
            return []
        lines = [status_line(self.target_linear_mps, self.target_angular_radps)]
        if self._presses_since_banner == STATUS_LINES_PER_BANNER:
            self._presses_since_banner = 0
            lines.append(BANNER)
        return lines

    def stop(self):
        """Targets and command to zero at once (no ramp)."""
        self.target_linear_mps = self.target_angular_radps = 0.0
        self.linear_mps = self.angular_radps = 0.0

    def step(self):
        """Move the command one loop's ramp towards the targets; returns (linear [m/s], angular [rad/s])."""
        self.linear_mps = ramp(self.linear_mps, self.target_linear_mps, LINEAR_RAMP_MPS)
        self.angular_radps = ramp(self.angular_radps, self.target_angular_radps, ANGULAR_RAMP_RADPS)
        return self.linear_mps, self.angular_radps
