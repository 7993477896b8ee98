"""The robot's trajectories during a submission's checks, drawn over the world from above, as PNG bytes: what an
instructor looks at to see at once that a robot drove backwards or never stopped. From the checks' ground-truth
trajectories and the world file tb3_sim loaded (tb3_sim.core.world_file), drawn from the scene primitives every
view shares (tb3_sim.core.scene_primitives: floor and markings, static shapes, models). Matplotlib with the Agg
backend (no display). No ROS import."""
import io

import matplotlib

matplotlib.use("Agg")
from matplotlib import pyplot  # noqa: E402  (after choosing the backend)
from matplotlib.patches import Circle, PathPatch  # noqa: E402
from matplotlib.path import Path  # noqa: E402
from matplotlib.transforms import Affine2D  # noqa: E402

from lab_grader.worlds import world_path  # noqa: E402
from tb3_sim.core.primitives import Disc, FilledPolygon, Image, Polyline, Text  # noqa: E402
from tb3_sim.core.scene_primitives import model_primitives, scene_primitives  # noqa: E402
from tb3_sim.core.text_outline import text_rings  # noqa: E402
from tb3_sim.core.world_file import load_world  # noqa: E402

FIGURE_INCHES = (6.4, 4.8)
DPI = 100
WALL_RGB = (0x55, 0x55, 0x55)
MODEL_RGB = (0xb0, 0x78, 0x40)
VERDICT_STYLES = {"pass": "-", "fail": "--", "error": ":"}
POINTS_PER_INCH = 72.0


def _colour(rgb):
    return tuple(channel / 255.0 for channel in rgb)


def _fill(axes, rings, rgb):
    vertices = [point for ring in rings for point in (*ring, ring[0])]
    codes = [code for ring in rings for code in
             (Path.MOVETO, *[Path.LINETO] * (len(ring) - 1), Path.CLOSEPOLY)]
    axes.add_patch(PathPatch(Path(vertices, codes), facecolor=_colour(rgb), edgecolor="none"))


def _polyline(axes, line):
    points = [*line.points, line.points[0]] if line.closed else list(line.points)
    (artist,) = axes.plot([p[0] for p in points], [p[1] for p in points], color=_colour(line.rgb),
                          solid_capstyle="butt", solid_joinstyle="round")
    artist.width_m = line.width   # matplotlib widths are in points: set once the scale is known (_set_widths)


def _image(axes, image):
    (sx, sy) = image.size
    artist = axes.imshow(image.pixels, extent=(-sx / 2, sx / 2, -sy / 2, sy / 2), interpolation="bilinear")
    artist.set_transform(Affine2D().rotate_deg(image.yaw_deg).translate(*image.center) + axes.transData)


# How matplotlib draws each kind of scene primitive.
ARTISTS = {
    FilledPolygon: lambda axes, p: _fill(axes, p.rings, p.rgb),
    Polyline: _polyline,
    Disc: lambda axes, p: axes.add_patch(Circle(p.center, p.radius, color=_colour(p.rgb))),
    Text: lambda axes, p: _fill(axes, [ring.tolist() for ring in text_rings(p)], p.rgb),
    Image: _image,
}


def _draw_world(axes, world):
    primitives = scene_primitives(world.floor, world.static_shapes, WALL_RGB)
    for model in world.models:
        primitives.extend(model_primitives(model.shape, model.pose, model.rgb or MODEL_RGB))
    for primitive in primitives:
        ARTISTS[type(primitive)](axes, primitive)


def _set_widths(axes, figure):
    """Stroke widths in metres to points, at the axes' final scale."""
    (x0, _), (x1, _) = axes.transData.transform([(0.0, 0.0), (1.0, 0.0)])
    points_per_m = abs(x1 - x0) / figure.dpi * POINTS_PER_INCH
    for line in axes.lines:
        if hasattr(line, "width_m"):
            line.set_linewidth(line.width_m * points_per_m)


def trajectory_png(world_name, checks) -> bytes:
    """PNG of every check's trajectory ([[t, x, y, yaw], ...] in its evidence) over world `world_name` (a shipped
    world or <package>/<file>: lab_grader.worlds), one colour per check, the line style by verdict (solid pass,
    dashed fail, dotted error)."""
    world = load_world(world_path(world_name))
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
        _set_widths(axes, figure)
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
