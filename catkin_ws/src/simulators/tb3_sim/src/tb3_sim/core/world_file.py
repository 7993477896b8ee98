"""World files: YAML describing static geometry and models, loaded into typed, immutable objects.

Format (every key is checked; unknown keys and bad values raise `WorldFileError` naming the file and key)::

    name: turtlebot3_world     # required: the world's name
    static_model: ros_symbol   # optional: /gazebo/model_states name of the static geometry
                               # (omit it for a world without static geometry, like Gazebo's empty world)
    static:                    # optional list of static shapes, world frame, metres
      - {type: segment, start: [x, y], end: [x, y]}          # zero-thickness wall
      - {type: polygon, points: [[x, y], [x, y], [x, y]]}    # solid, convex, 3-8 vertices
      - {type: circle, center: [x, y], radius: r}            # solid disc (a pillar)
      - {type: box, center: [x, y], size: [sx, sy], yaw: 0.0}  # solid rectangle as Gazebo gives a box (yaw in
                                                             # rad, default 0), stored as a Polygon
      # each static item also takes an optional `height` (m above the floor, default 1.0) and `color`
    static_models:             # optional, instead of static_model + static: several named static models, each
      - name: navigation       # listed in /gazebo/model_states at pose 0 in this order
        static: [...]          # static shapes as under `static:`
    floor:                     # optional; omitted: Gazebo's infinite grey ground plane (model `ground_plane`);
                               # given: the floor model is the ground and no `ground_plane` is listed
      size: [sx, sy]           # the visible floor rectangle, m; outside it a camera sees the background grey
      center: [x, y]           # optional, default [0, 0]
      color: white             # optional base colour, default white
      image: {file: f.png, size: [sx, sy], center: [x, y], yaw_deg: 0}  # optional PNG/JPEG over the base
                               # colour (path relative to this file, at most 4096 px a side; top row at +y)
      markings:                # optional, drawn in order over the image; `color` required on each
        - {type: rectangle, center: [x, y], size: [w, h], yaw_deg: 0.0, color: c}
        - {type: polygon, points: [[x, y], ...], color: c}             # any simple polygon
        - {type: circle, center: [x, y], radius: r, color: c}
        - {type: arc, center: [x, y], radius: r, start_deg: a0, end_deg: a1, width: w, color: c}  # anticlockwise
        - {type: polyline, points: [[x, y], ...], width: w, color: c, closed: false}
        - {type: curve, points: [p0, c1, c2, p1, ...], width: w, color: c}   # cubic Béziers as SVG's "C"
        - {type: text, text: "A", position: [x, y], height: h, angle_deg: 0.0, color: c, bold: false}
        # `width: w` on rectangle/polygon/circle draws the outline only; `dash: [on, off]` (m, with width) dashes
        # a stroke; `arrow: start|end` on arc/polyline/curve adds an arrowhead `arrow_length` m long (3 x width)
        # (see core.floor for the meaning of every field)
    models:                    # optional list of named models (movable with set_model_state)
      - name: box1             # required, unique, not `ground_plane` nor the static_model name
        type: box              # box | cylinder
        size: [sx, sy, sz]     # box only: m; sz is the height
        radius: r              # cylinder only: m
        height: h              # cylinder only: m (SDF's `length`)
        pose: [x, y, yaw]      # optional, default [0, 0, 0]: m, m, rad in the world frame
        static: false          # optional, default false: a static model is never pushed
        mass: 1.0              # optional, kg, default 1.0 (dynamic models only)
        color: red             # optional: what the camera sees (default: Gazebo's untextured grey)

`color` is a colour name (red, green, blue, yellow, orange, purple, white, black, grey, ...), a hex string
("#ff8800"), a Gazebo material name ("Gazebo/Red"), or [r, g, b] with each in [0, 1]. Static shapes default to
the wall grey of materials.DEFAULT_WALL_RGB, models to Gazebo's default model grey.

The robot is not part of a world file: its spawn pose is given by the caller (launch args x_pos, y_pos, yaw).
Objects whose height is below the LiDAR plane (0.132 m) collide but are not seen by the scan.
"""

import math
from dataclasses import dataclass
from pathlib import Path
from typing import Optional, Tuple, Union

import yaml

from tb3_sim.core.errors import WorldFileError
from tb3_sim.core.floor import Floor
from tb3_sim.core.floor_file import parse_floor
from tb3_sim.core.geometry import Pose2D
from tb3_sim.core.materials import colour_from_name_or_hex, rgb_from_unit
from tb3_sim.core.shapes import DEFAULT_STATIC_HEIGHT_M, Box, Circle, Cylinder, Polygon, Rgb, Segment

GROUND_PLANE_NAME = "ground_plane"

# Gazebo gives a spawned link without an <inertial> a mass of 1 kg.
DEFAULT_MODEL_MASS_KG = 1.0

# Box2D's b2_maxPolygonVertices is 16, but 8 keeps polygons cheap and matches flatland's limit.
MAX_POLYGON_VERTICES = 8

SHIPPED_WORLDS_DIR = Path(__file__).resolve().parents[3] / "worlds"

_TOP_KEYS = {"name": True, "static_model": False, "static": False, "static_models": False, "models": False,
             "floor": False}
_STATIC_MODEL_KEYS = {"name": True, "static": True}
_STATIC_KEYS = {
    "box": {"type": True, "center": True, "size": True, "yaw": False, "height": False, "color": False},
    "segment": {"type": True, "start": True, "end": True, "height": False, "color": False},
    "polygon": {"type": True, "points": True, "height": False, "color": False},
    "circle": {"type": True, "center": True, "radius": True, "height": False, "color": False},
}
_MODEL_KEYS = {
    "box": {"name": True, "type": True, "size": True, "pose": False, "static": False, "mass": False,
            "color": False},
    "cylinder": {"name": True, "type": True, "radius": True, "height": True, "pose": False,
                 "static": False, "mass": False, "color": False},
}


@dataclass(frozen=True)
class ModelSpec:
    """A named model: its shape, its pose in the world frame, whether it is static, its mass in kg, and its
    colour for the camera ((r, g, b) 0-255, or None for Gazebo's default grey)."""

    name: str
    shape: Union[Box, Cylinder]
    pose: Pose2D = Pose2D()
    static: bool = False
    mass_kg: float = DEFAULT_MODEL_MASS_KG
    rgb: Optional[Rgb] = None


@dataclass(frozen=True)
class StaticModel:
    """A named static model: its shapes (world frame), listed in /gazebo/model_states at pose 0."""

    name: str
    shapes: Tuple[Union[Segment, Polygon, Circle], ...]


@dataclass(frozen=True)
class WorldDescription:
    """Everything a world file says. `source` is the file it came from (for messages).

    `static_shapes` holds every static shape of the world; `static_models` names the models they belong to when
    the file lists several (`static_models:`); the single-model form sets `static_model` instead. `floor` is the
    floor layer, or None for Gazebo's plain infinite ground plane."""

    name: str
    static_model: Optional[str] = None
    static_shapes: Tuple[Union[Segment, Polygon, Circle], ...] = ()
    models: Tuple[ModelSpec, ...] = ()
    source: str = "<memory>"
    static_models: Tuple[StaticModel, ...] = ()
    floor: Optional[Floor] = None

    @property
    def static_model_names(self):
        """The static models' names for /gazebo/model_states, in file order (after `ground_plane`)."""
        if self.static_models:
            return tuple(model.name for model in self.static_models)
        return (self.static_model,) if self.static_model else ()


def shipped_world_path(world_name):
    """Path of a world shipped with tb3_sim, e.g. ``shipped_world_path("empty")`` -> worlds/empty.yaml."""
    return SHIPPED_WORLDS_DIR / f"{world_name}.yaml"


def load_world(path):
    """Read and validate the world file at `path`; return a `WorldDescription`.

    Raises `WorldFileError` if the file cannot be read, is not YAML, or breaks the format above.
    """
    path = Path(path)
    try:
        text = path.read_text(encoding="utf-8")
    except OSError as error:
        raise WorldFileError(path, "<file>", f"cannot read: {error.strerror}") from error
    try:
        data = yaml.safe_load(text)
    except yaml.YAMLError as error:
        raise WorldFileError(path, "<file>", f"not valid YAML: {error}") from error
    return parse_world(data, str(path))


def parse_world(data, source="<memory>"):
    """Validate already-parsed YAML `data` (a dict) and return a `WorldDescription`. A floor image's path is
    relative to the folder of `source` (the current folder for "<memory>")."""
    reader = _Reader(source)
    reader.keys(data, "<top>", _TOP_KEYS)
    name = reader.name(data["name"], "name")
    taken = {GROUND_PLANE_NAME}
    static_model = None
    if "static_model" in data:
        static_model = reader.unique_name(data["static_model"], "static_model", taken)
    static_shapes = reader.static_shapes(data.get("static", []), "static")
    static_models = ()
    if "static_models" in data:
        for single in ("static_model", "static"):
            if single in data:
                reader.fail(single, "give either `static_models` or `static_model`/`static`, not both")
        static_models = tuple(reader.static_model(item, f"static_models[{i}]", taken)
                              for i, item in enumerate(reader.list(data["static_models"], "static_models")))
        static_shapes = tuple(shape for model in static_models for shape in model.shapes)
    models = tuple(reader.model(item, f"models[{i}]", taken)
                   for i, item in enumerate(reader.list(data.get("models", []), "models")))
    floor = None
    if "floor" in data:
        base_dir = Path(source).parent if source != "<memory>" else Path.cwd()
        floor = parse_floor(reader, data["floor"], "floor", base_dir)
    return WorldDescription(name, static_model, static_shapes, models, source, static_models, floor)


class _Reader:
    """Checks values of one file and raises `WorldFileError` with the file and key on the first problem."""

    def __init__(self, source):
        self.source = source

    def fail(self, key, problem):
        raise WorldFileError(self.source, key, problem)

    def keys(self, value, key, spec):
        if not isinstance(value, dict):
            self.fail(key, f"expected a mapping, got {type(value).__name__}")
        for found in value:
            if found not in spec:
                where = found if key == "<top>" else f"{key}.{found}"
                self.fail(where, f"unknown key (allowed: {', '.join(sorted(spec))})")
        for wanted, required in spec.items():
            if required and wanted not in value:
                where = wanted if key == "<top>" else f"{key}.{wanted}"
                self.fail(where, "missing required key")

    def list(self, value, key):
        if not isinstance(value, list):
            self.fail(key, f"expected a list, got {type(value).__name__}")
        return value

    def name(self, value, key):
        if not isinstance(value, str) or not value or any(c.isspace() for c in value):
            self.fail(key, f"expected a non-empty name without spaces, got {value!r}")
        return value

    def unique_name(self, value, key, taken):
        """A model name not in `taken` (which it joins)."""
        name = self.name(value, key)
        if name == GROUND_PLANE_NAME:
            self.fail(key, f"'{GROUND_PLANE_NAME}' is reserved for the ground plane")
        if name in taken:
            self.fail(key, f"name '{name}' is already used in this world")
        taken.add(name)
        return name

    def number(self, value, key, positive=False):
        if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value):
            self.fail(key, f"expected a finite number, got {value!r}")
        if positive and value <= 0:
            self.fail(key, f"expected a number > 0, got {value!r}")
        return float(value)

    def numbers(self, value, key, count, positive=False):
        if not isinstance(value, list) or len(value) != count:
            self.fail(key, f"expected a list of {count} numbers, got {value!r}")
        return tuple(self.number(v, f"{key}[{i}]", positive) for i, v in enumerate(value))

    def kind(self, item, key, allowed):
        if not isinstance(item, dict):
            self.fail(key, f"expected a mapping, got {type(item).__name__}")
        kind = item.get("type")
        if kind not in allowed:
            self.fail(f"{key}.type", f"expected one of {', '.join(sorted(allowed))}, got {kind!r}")
        self.keys(item, key, allowed[kind])
        return kind

    def height(self, item, key):
        return self.number(item.get("height", DEFAULT_STATIC_HEIGHT_M), f"{key}.height", positive=True)

    def static_shapes(self, value, key):
        return tuple(self.static_shape(item, f"{key}[{i}]") for i, item in enumerate(self.list(value, key)))

    def static_model(self, item, key, taken):
        self.keys(item, key, _STATIC_MODEL_KEYS)
        return StaticModel(self.unique_name(item["name"], f"{key}.name", taken),
                           self.static_shapes(item["static"], f"{key}.static"))

    def static_shape(self, item, key):
        kind = self.kind(item, key, _STATIC_KEYS)
        if kind == "box":
            center = self.numbers(item["center"], f"{key}.center", 2)
            size = self.numbers(item["size"], f"{key}.size", 2, positive=True)
            height = self.height(item, key)
            placed = Pose2D(*center, self.number(item.get("yaw", 0.0), f"{key}.yaw"))
            return Polygon(tuple(placed.compose(x, y) for x, y in Box(*size, height).corners()), height,
                           self.colour(item, key))
        if kind == "segment":
            start = self.numbers(item["start"], f"{key}.start", 2)
            end = self.numbers(item["end"], f"{key}.end", 2)
            if start == end:
                self.fail(f"{key}.end", "segment has zero length")
            return Segment(start, end, self.height(item, key), self.colour(item, key))
        if kind == "polygon":
            return Polygon(self.polygon_points(item["points"], f"{key}.points"), self.height(item, key),
                           self.colour(item, key))
        center = self.numbers(item["center"], f"{key}.center", 2)
        radius = self.number(item["radius"], f"{key}.radius", positive=True)
        return Circle(center, radius, self.height(item, key), self.colour(item, key))

    def colour(self, item, key):
        """The optional `color` of `item` as (r, g, b) 0-255, or None."""
        if "color" not in item:
            return None
        value, where = item["color"], f"{key}.color"
        if isinstance(value, list):
            channels = self.numbers(value, where, 3)
            if not all(0.0 <= c <= 1.0 for c in channels):
                self.fail(where, f"expected [r, g, b] with each in [0, 1], got {value!r}")
            return rgb_from_unit(channels)
        if not isinstance(value, str):
            self.fail(where, f"expected a colour name, '#rrggbb', a Gazebo material or [r, g, b], got {value!r}")
        try:
            return colour_from_name_or_hex(value)
        except ValueError as error:
            self.fail(where, str(error))

    def polygon_points(self, value, key):
        if not isinstance(value, list) or not 3 <= len(value) <= MAX_POLYGON_VERTICES:
            self.fail(key, f"expected a list of 3 to {MAX_POLYGON_VERTICES} [x, y] points, got {value!r}")
        points = tuple(self.numbers(p, f"{key}[{i}]", 2) for i, p in enumerate(value))
        if not _is_strictly_convex(points):
            self.fail(key, "polygon must be convex with no repeated or collinear vertices")
        return points

    def model(self, item, key, taken):
        kind = self.kind(item, key, _MODEL_KEYS)
        name = self.unique_name(item["name"], f"{key}.name", taken)
        if kind == "box":
            sx, sy, sz = self.numbers(item["size"], f"{key}.size", 3, positive=True)
            shape = Box(sx, sy, sz)
        else:
            shape = Cylinder(self.number(item["radius"], f"{key}.radius", positive=True),
                             self.number(item["height"], f"{key}.height", positive=True))
        pose = Pose2D(*self.numbers(item.get("pose", [0.0, 0.0, 0.0]), f"{key}.pose", 3))
        static = item.get("static", False)
        if not isinstance(static, bool):
            self.fail(f"{key}.static", f"expected true or false, got {static!r}")
        mass = self.number(item.get("mass", DEFAULT_MODEL_MASS_KG), f"{key}.mass", positive=True)
        return ModelSpec(name, shape, pose, static, mass, self.colour(item, key))


def _is_strictly_convex(points):
    """True if the closed polygon turns the same way at every vertex and winds exactly once.

    Checking the winding rejects self-intersecting stars, whose turns all have the same sign too.
    """
    n = len(points)
    turns = []
    for i in range(n):
        (ax, ay), (bx, by), (cx, cy) = points[i], points[(i + 1) % n], points[(i + 2) % n]
        ex, ey, fx, fy = bx - ax, by - ay, cx - bx, cy - by
        cross, dot = ex * fy - ey * fx, ex * fx + ey * fy
        if abs(cross) < 1e-12:
            return False
        turns.append(math.atan2(cross, dot))
    same_sign = all(t > 0 for t in turns) or all(t < 0 for t in turns)
    return same_sign and math.isclose(abs(sum(turns)), 2.0 * math.pi, abs_tol=1e-6)
