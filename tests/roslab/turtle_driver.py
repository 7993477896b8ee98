"""Drive a turtlesim core Turtle with a controller in a closed loop, for the controller unit tests (no ROS)."""

from turtlesim.core.canvas import Canvas
from turtlesim.core.constants import DT


def drive(turtle, controller_step, ticks):
    """Run turtle ticks at 62.5 Hz; each pose goes to `controller_step`, whose command takes
    effect from the next tick (as a published Twist reaches the next spinOnce). Returns the
    poses; stops early when `controller_step` returns the string 'done'."""
    canvas = Canvas()
    poses = []
    for k in range(1, ticks + 1):
        now = k * DT
        pose = turtle.update(DT, now, canvas).pose
        poses.append(pose)
        command = controller_step(pose)
        if command == 'done':
            break
        if command is not None:
            turtle.set_command(command[0], 0.0, command[1], now)
    return poses
