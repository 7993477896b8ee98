"""Gazebo's physics properties (/gazebo/get_physics_properties, set_physics_properties) over tb3_sim's pacing.

In Gazebo the real-time factor is max_update_rate x time_step: 1000 updates per wall second of 1 ms each is real
time, 5000 of 1 ms is 5x, and max_update_rate 0 runs as fast as possible. Tutorials speed a simulation up by
setting those two numbers, so here their product sets the pacing (the node's real_time_factor, 0 = unpaced),
while the physics step itself stays the simulator's own: the two numbers are kept and reported back as given.
Gravity is kept and reported too; a 2D simulator has no use for it.

Gazebo accepts any max_update_rate; here a product below MIN_REAL_TIME_FACTOR (0.01: one simulated second per
100 wall seconds) is refused, because the loop would publish /clock once in hours or days (max_update_rate
0.0001 with a 1 ms step waits about a day between steps) and every sim-time node would stand still.
"""

import math
from dataclasses import dataclass
from typing import Tuple

from tb3_sim.core.errors import BadRequestError

GAZEBO_GRAVITY = (0.0, 0.0, -9.8)
MIN_REAL_TIME_FACTOR = 0.01


@dataclass(frozen=True)
class PhysicsProperties:
    """`time_step_s` (> 0), `max_update_rate_hz` (>= 0; 0: as fast as possible) and `gravity` (m/s^2, x y z)."""

    time_step_s: float
    max_update_rate_hz: float
    gravity: Tuple[float, float, float] = GAZEBO_GRAVITY

    @property
    def real_time_factor(self):
        """Sim seconds per wall second, 0 meaning as fast as possible (Pacer's convention)."""
        return self.max_update_rate_hz * self.time_step_s

    @classmethod
    def for_pacing(cls, step_s, real_time_factor):
        """The properties of a simulator stepping `step_s` at `real_time_factor` (0: unpaced)."""
        return cls(step_s, real_time_factor / step_s)


def physics_properties(time_step_s, max_update_rate_hz, gravity):
    """Validated PhysicsProperties from a request; raises BadRequestError naming the bad field."""
    if not (math.isfinite(time_step_s) and time_step_s > 0.0):
        raise BadRequestError(f"time_step must be a finite number of seconds > 0, got {time_step_s}")
    if not (math.isfinite(max_update_rate_hz) and max_update_rate_hz >= 0.0):
        raise BadRequestError(f"max_update_rate must be a finite rate >= 0 (0: as fast as possible), got "
                              f"{max_update_rate_hz}")
    real_time_factor = time_step_s * max_update_rate_hz
    if not (real_time_factor == 0.0 or MIN_REAL_TIME_FACTOR <= real_time_factor < math.inf):
        raise BadRequestError(f"max_update_rate x time_step is the real-time factor and must be 0 (as fast as "
                              f"possible) or in [{MIN_REAL_TIME_FACTOR}, inf), got {max_update_rate_hz} x "
                              f"{time_step_s} = {real_time_factor:g}: the simulation would stand still")
    if not all(math.isfinite(g) for g in gravity):
        raise BadRequestError(f"gravity must hold finite numbers, got {tuple(gravity)}")
    return PhysicsProperties(float(time_step_s), float(max_update_rate_hz), tuple(float(g) for g in gravity))
