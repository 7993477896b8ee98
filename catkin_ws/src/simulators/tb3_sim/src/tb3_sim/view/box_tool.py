"""The Gazebo box tool as mouse gestures on the top-down view, over the world (no Qt, no ROS here).

- a left click on empty floor spawns a box (`box_1`, `box_2`, ...: a BOX_SIZE_M cube of 1 kg, dynamic);
- a left press on a box or cylinder model and a drag moves it (a teleport per mouse move, like dragging in
  Gazebo's move mode); the release leaves it at rest;
- a right click on a model deletes it.
The robot and the static world geometry are never picked. A box that would overlap the robot or another model
is not placed. Coordinates are world metres; the caller converts pixels. Every method takes the world lock.
"""

import math

from tb3_sim.core.errors import SimError
from tb3_sim.core.geometry import Pose2D
from tb3_sim.core.shapes import Box
from tb3_sim.core.world_file import ModelSpec

BOX_SIZE_M = 0.3
BOX_NAME_PREFIX = "box_"


def model_at(world, x, y):
    """Name of the box or cylinder model whose footprint contains (x, y), the newest first; or None."""
    for model in reversed(world.models()):
        pose, shape = model.pose, model.spec.shape
        c, s = math.cos(pose.yaw), math.sin(pose.yaw)
        dx, dy = x - pose.x, y - pose.y
        local_x, local_y = c * dx + s * dy, -s * dx + c * dy
        if isinstance(shape, Box):
            inside = abs(local_x) <= shape.size_x / 2 and abs(local_y) <= shape.size_y / 2
        else:
            inside = math.hypot(local_x, local_y) <= shape.radius
        if inside:
            return model.name
    return None


def next_box_name(world):
    """The first free name box_1, box_2, ..."""
    number = 1
    while world.has_model(f"{BOX_NAME_PREFIX}{number}"):
        number += 1
    return f"{BOX_NAME_PREFIX}{number}"


class BoxTool:
    """Mouse gestures -> world edits. `sim` offers locked_world() and teleported() (the ROS node does)."""

    def __init__(self, sim):
        self._sim = sim
        self._dragging = None

    def left_press(self, x, y):
        """Start dragging the model under (x, y), or spawn a box there. Returns what happened, for the log."""
        with self._sim.locked_world() as world:
            picked = model_at(world, x, y)
            if picked is not None:
                self._dragging = picked
                return f"dragging '{picked}'"
            name = next_box_name(world)
            try:
                world.spawn_model(ModelSpec(name, Box(BOX_SIZE_M, BOX_SIZE_M, BOX_SIZE_M), Pose2D(x, y, 0.0)))
            except SimError as error:
                return f"no box placed: {error}"
            return f"placed '{name}' at ({x:.2f}, {y:.2f})"

    def drag(self, x, y):
        """Move the model being dragged so its origin is at (x, y), keeping its heading."""
        if self._dragging is None:
            return
        with self._sim.locked_world() as world:
            if not world.has_model(self._dragging):
                self._dragging = None
                return
            yaw = world.get_model_state(self._dragging).pose.yaw
            world.set_model_state(self._dragging, Pose2D(x, y, yaw))
            self._sim.teleported()

    def release(self):
        self._dragging = None

    def right_click(self, x, y):
        """Delete the model under (x, y), if any. Returns what happened, or None."""
        with self._sim.locked_world() as world:
            picked = model_at(world, x, y)
            if picked is None:
                return None
            try:
                world.delete_model(picked)
            except SimError as error:
                return f"not deleted: {error}"
            return f"deleted '{picked}'"
