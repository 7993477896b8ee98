"""The page <-> server protocol: JSON text frames over one WebSocket (/ws), and the validation of what a page
sends. No ROS import: the server hands validated commands to the ROS bridge.

Server -> page (every frame has "type"):
  hello     {"version": 1, "teleop_limits": {"robot": [linear m/s, angular rad/s], "turtle1": [...]},
             "world_frame": "odom"}                                once, on connect
  world     {"bounds": [xmin, ymin, xmax, ymax], "static": [shape, ...], "models": [model, ...],
             "robots": [model, ...], "scene": [primitive, ...] | null}  on connect and whenever it changes (<= 2 Hz)
            scene: tb3_sim's /gazebo/scene_primitives as they are (floor layer and static shapes; null without it):
                   {"kind": "FilledPolygon", "rings", "rgb"} | {"kind": "Polyline", "points", "width", "rgb",
                   "closed"} | {"kind": "Disc", "center", "radius", "rgb"} | {"kind": "Text", "text", "position",
                   "height", "angle_deg", "bold", "rgb"} | {"kind": "Image", "src" (PNG data URL), "center", "size",
                   "yaw_deg"}; metres, [r, g, b] 0-255 (null: the page's wall colour); drawn instead of "static"
            shape: {"kind": "polygon", "points": [[x, y], ...]} | {"kind": "segment", "points": [[x, y], [x, y]]}
                   | {"kind": "circle", "x", "y", "r"}
            model: {"name", "kind": "box" | "circle", "x", "y", "yaw", "sx", "sy" (box) | "r" (circle)}
  state     {"stamp_ms": wall ms when the newest state arrived, "sim_time": s | null, "rtf": float | null,
             "robot": {"x", "y", "yaw", "v", "w"} | null,
             "trail": {"reset": bool, "points": [[x, y], ...]} (reset true: replace the page's trail with
                      points; false: append them; a page keeps at most 3000 points),
             "scan": [[x, y], ...] (world-frame LiDAR hits of the newest sweep)}      <= 25 per second
  turtlesim {"stamp_ms", "background": [r, g, b], "turtles": [{"name", "x", "y", "theta"}], "size_m": 11.08...,
             "canvas": true | false (false: turtlesim runs without ~publish_canvas; trails cannot be shown)}
  canvas    {"png": base64 PNG of turtlesim's 500x500 pen canvas}                     when it changes
  camera    {"jpeg": base64 JPEG thumbnail, "width", "height"}   only while the page asked for it (<= 5 Hz)
  graph     {"nodes": [name], "topics": [{"name", "type", "hz": float | null, "publishers": [node],
             "subscribers": [node]}], "services": [{"name", "node"}]}                 every 2 s
  echo      {"topic", "text": the latest message as YAML-like text}                    <= 5 Hz, while selected
  reply     {"id": the request's id, "ok": bool, "text": what happened}               once per request
  error     {"text": what was wrong with a frame}                                      for each bad frame

Page -> server (every frame has "type"; "id" is an integer the reply carries back):
  teleop         {"target": "robot" | "turtle1", "linear": m/s, "angular": rad/s}
                 repeated at ~10 Hz while a key or button is held, and zeros once on release. The server
                 publishes at a fixed 10 Hz while commands keep coming and zero once they stop (0.3 s) or
                 the page goes away.
  spawn_box      {"id", "x", "y"}                    a 0.3 m box on the floor at (x, y)
  move_model     {"id", "name", "x", "y"}            set_model_state, keeping the model's heading
  delete_model   {"id", "name"}
  reset_world    {"id"}
  service_fields {"id", "service"}                   reply text: JSON [{"name", "type"}] of the request's fields
  call_service   {"id", "service", "fields": {name: value}}
  echo           {"topic": name | null}              select the topic to echo (null: none)
  camera         {"on": bool}                        camera thumbnails on or off
"""
import json
import math
import re
from typing import Any, Dict, NamedTuple, Optional

MAX_FRAME_BYTES = 4096
"""Bigger frames are refused before parsing: no command needs more."""

TELEOP_TARGETS = ("robot", "turtle1")
NAME_PATTERN = re.compile(r"^/?[A-Za-z][A-Za-z0-9_/]{0,199}$")
"""A ROS graph name (absolute or relative) or a model name, at most 200 characters."""
COORDINATE_LIMIT_M = 1000.0
MAX_FIELDS = 32
MAX_FIELD_TEXT = 256


class ProtocolError(ValueError):
    """A frame the server refuses; its text is sent back to the page as an `error` (or a failed `reply`)."""

    def __init__(self, text, request_id=None):
        super().__init__(text)
        self.request_id = request_id


class Command(NamedTuple):
    """A validated page command: its type, request id (None for teleop, echo and camera) and arguments."""

    type: str
    id: Optional[int]
    args: Dict[str, Any]


def _number(frame, key, request_id, limit):
    value = frame.get(key)
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        raise ProtocolError("{} must be a number, got {}".format(key, json.dumps(value)[:40]), request_id)
    try:
        number = float(value)
    except OverflowError:   # an integer of hundreds of digits: JSON has no limit, a float does
        number = math.inf
    if not math.isfinite(number) or abs(number) > limit:
        raise ProtocolError("{} must be a finite number within +-{:g}, got {}".format(
            key, limit, json.dumps(value)[:40]), request_id)
    return number


def _name(frame, key, request_id):
    value = frame.get(key)
    if not isinstance(value, str) or not NAME_PATTERN.match(value):
        raise ProtocolError("{} must be a name (letters, digits, _ and /, at most 200), got {}".format(
            key, json.dumps(value)[:60]), request_id)
    return value


def _request_id(frame):
    value = frame.get("id")
    if isinstance(value, bool) or not isinstance(value, int) or not 0 <= value < 2 ** 31:
        raise ProtocolError("id must be an integer from 0 to 2^31-1, got {}".format(json.dumps(value)[:40]))
    return value


def _teleop(frame, limits):
    target = frame.get("target")
    if target not in TELEOP_TARGETS:
        raise ProtocolError("target must be one of {}, got {}".format(TELEOP_TARGETS, json.dumps(target)[:40]))
    linear_limit, angular_limit = limits[target]
    return {"target": target, "linear": _number(frame, "linear", None, linear_limit),
            "angular": _number(frame, "angular", None, angular_limit)}


def _fields(frame, request_id):
    fields = frame.get("fields", {})
    if not isinstance(fields, dict) or len(fields) > MAX_FIELDS:
        raise ProtocolError("fields must be an object of at most {} name: value pairs".format(MAX_FIELDS), request_id)
    for name, value in fields.items():
        if not isinstance(value, (str, int, float, bool)) or (isinstance(value, str) and len(value) > MAX_FIELD_TEXT):
            raise ProtocolError("field {} must be a string (at most {} characters), number or boolean".format(
                name[:40], MAX_FIELD_TEXT), request_id)
    return fields


def parse_command(text, teleop_limits):
    """The Command in one text frame. `teleop_limits` maps each teleop target to (linear m/s, angular rad/s):
    a faster command is refused, not clamped, so the robot never moves faster than a key asks.

    Raises ProtocolError naming the problem (its request_id set when the frame had a valid id)."""
    if len(text) > MAX_FRAME_BYTES:
        raise ProtocolError("frame too large: {} characters, at most {}".format(len(text), MAX_FRAME_BYTES))
    try:
        frame = json.loads(text)
    except ValueError as error:
        raise ProtocolError("not JSON: {}".format(error)) from None
    except RecursionError:
        raise ProtocolError("not JSON this server reads: nested too deeply") from None
    if not isinstance(frame, dict):
        raise ProtocolError("a frame must be a JSON object with a \"type\"")
    kind = frame.get("type")
    if kind == "teleop":
        return Command(kind, None, _teleop(frame, teleop_limits))
    if kind == "echo":
        topic = frame.get("topic")
        return Command(kind, None, {"topic": None if topic is None else _name(frame, "topic", None)})
    if kind == "camera":
        if not isinstance(frame.get("on"), bool):
            raise ProtocolError("on must be true or false")
        return Command(kind, None, {"on": frame["on"]})
    if kind not in ("spawn_box", "move_model", "delete_model", "reset_world", "service_fields", "call_service"):
        raise ProtocolError("unknown type {}".format(json.dumps(kind)[:40]))
    request_id = _request_id(frame)
    args = {}
    if kind in ("spawn_box", "move_model"):
        args["x"] = _number(frame, "x", request_id, COORDINATE_LIMIT_M)
        args["y"] = _number(frame, "y", request_id, COORDINATE_LIMIT_M)
    if kind in ("move_model", "delete_model"):
        args["name"] = _name(frame, "name", request_id)
    if kind in ("service_fields", "call_service"):
        args["service"] = _name(frame, "service", request_id)
    if kind == "call_service":
        args["fields"] = _fields(frame, request_id)
    return Command(kind, request_id, args)


def frame(kind, **content):
    """One server -> page frame as JSON text (non-finite numbers become null, as JSON has none)."""
    content = {"type": kind, **content}
    try:
        return json.dumps(content, separators=(",", ":"), allow_nan=False)
    except ValueError:   # rare (an echoed value, a real-time factor before time moves): walk the frame once
        return json.dumps(_finite(content), separators=(",", ":"))


def _finite(value):
    if isinstance(value, float):
        return value if math.isfinite(value) else None
    if isinstance(value, dict):
        return {key: _finite(item) for key, item in value.items()}
    if isinstance(value, (list, tuple)):
        return [_finite(item) for item in value]
    return value
