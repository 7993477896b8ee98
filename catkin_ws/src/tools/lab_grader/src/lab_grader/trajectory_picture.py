"""The robot's trajectories during a submission's checks, drawn over the world from above, as PNG bytes: what an
instructor looks at to see at once that a robot drove backwards or never stopped. From the checks' ground-truth
trajectories and the world file tb3_sim loaded (tb3_sim.core.world_file). Matplotlib with the Agg backend (no
display). No ROS import."""
import io

import matplotlib

matplotlib.use("Agg")
from matplotlib import pyplot  # noqa: E402  (after choosing the backend)
from matplotlib.patches import Circle, Polygon, Rectangle  # noqa: E402
from matplotlib.transforms import Affine2D  # noqa: E402

from tb3_sim.core.shapes import Box, Segment  # noqa: E402
from tb3_sim.core.shapes import Circle as CircleShape  # noqa: E402
from tb3_sim.core.world_file import load_world, shipped_world_path  # noqa: E402

FIGURE_INCHES = (6.4, 4.8)
DPI = 100
WALL_COLOUR = "#555555"
MODEL_COLOUR = "#b07840"
VERDICT_STYLES = {"pass": "-", "fail": "--", "error": ":"}


def _draw_world(axes, world):
    for shape in world.static_shapes:
        if isinstance(shape, Segment):
            axes.plot([shape.start[0], shape.end[0]], [shape.start[1], shape.end[1]], color=WALL_COLOUR, lw=2)
        elif isinstance(shape, CircleShape):
            axes.add_patch(Circle(shape.center, shape.radius, color=WALL_COLOUR))
        else:
            axes.add_patch(Polygon(shape.points, closed=True, color=WALL_COLOUR))
    for model in world.models:
        x, y, yaw = model.pose.x, model.pose.y, model.pose.yaw
        if isinstance(model.shape, Box):
            patch = Rectangle((-model.shape.size_x / 2, -model.shape.size_y / 2), model.shape.size_x,
                              model.shape.size_y, color=MODEL_COLOUR)
            patch.set_transform(Affine2D().rotate(yaw).translate(x, y) + axes.transData)
            axes.add_patch(patch)
        else:
            axes.add_patch(Circle((x, y), model.shape.radius, color=MODEL_COLOUR))


def trajectory_png(world_name, checks) -> bytes:
    """PNG of every check's trajectory ([[t, x, y, yaw], ...] in its evidence) over world `world_name`, one colour
    per check, the line style by verdict (solid pass, dashed fail, dotted error)."""
    world = load_world(shipped_world_path(world_name))
    figure, axes = pyplot.subplots(figsize=FIGURE_INCHES, dpi=DPI)
    try:
        _draw_world(axes, world)
        for check in checks:
            points = (check.get("evidence") or {}).get("trajectory") or []
            if len(points) < 2:
                continue
            xs, ys = [point[1] for point in points], [point[2] for point in points]
            axes.plot(xs, ys, VERDICT_STYLES.get(check["verdict"], "-"), lw=1.5, label=check["id"])
            axes.plot(xs[-1:], ys[-1:], "o", ms=3, color=axes.lines[-1].get_color())
        axes.plot([0], [0], "k+", ms=10, label="start")
        axes.set_aspect("equal")
        axes.autoscale_view()
        axes.grid(True, lw=0.3)
        axes.set_xlabel("x (m)")
        axes.set_ylabel("y (m)")
        axes.set_title("Ground-truth trajectories in {} (solid pass, dashed fail, dotted error)".format(world_name),
                       fontsize=9)
        axes.legend(fontsize=7, loc="upper left", bbox_to_anchor=(1.02, 1.0), borderaxespad=0)  # beside the world
        buffer = io.BytesIO()
        figure.savefig(buffer, format="png", bbox_inches="tight")
        return buffer.getvalue()
    finally:
        pyplot.close(figure)
