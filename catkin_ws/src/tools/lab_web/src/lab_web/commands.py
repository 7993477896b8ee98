"""What a page may send, as data: each command a panel accepts is a CommandSpec (its fields, each with a
validator, and whether it is a request with a reply), and one registry {type: CommandSpec} built from the panels
(lab_web.panels.COMMANDS) parses every frame. No ROS import.

A validator is a callable (frame, key, request_id, args so far) -> the value, raising ProtocolError naming the
key; `args so far` lets a field depend on an earlier one (a teleop speed's limit on its target).
"""
import json
import math
import re
from typing import Any, Callable, Dict, NamedTuple, Optional, Tuple

MAX_FRAME_BYTES = 4096
"""Bigger frames are refused before parsing: no command needs more."""
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
    """A validated page command: its type, request id (None for commands without a reply) and arguments."""

    type: str
    id: Optional[int]
    args: Dict[str, Any]


Validator = Callable[[dict, str, Optional[int], dict], Any]


class CommandSpec(NamedTuple):
    """One command: `fields` in validation order, `doc` (its line in the protocol), `pool`: the kind of worker
    that runs it, "" for one the server runs at once (no id, no reply), else a request (with an id, answered by
    a `reply`) run by that pool's workers (lab_web.server.RequestPool)."""

    fields: Tuple[Tuple[str, Validator], ...]
    doc: str
    pool: str = ""

    @property
    def request(self):
        return bool(self.pool)


def _shown(value, length=40):
    return json.dumps(value)[:length]


def number(limit):
    """A finite JSON number within +-limit."""
    def check(frame, key, request_id, _args):
        value = frame.get(key)
        if isinstance(value, bool) or not isinstance(value, (int, float)):
            raise ProtocolError("{} must be a number, got {}".format(key, _shown(value)), request_id)
        try:
            result = float(value)
        except OverflowError:   # an integer of hundreds of digits: JSON has no limit, a float does
            result = math.inf
        if not math.isfinite(result) or abs(result) > limit:
            raise ProtocolError("{} must be a finite number within +-{:g}, got {}".format(
                key, limit, _shown(value)), request_id)
        return result
    return check


def coordinate():
    return number(COORDINATE_LIMIT_M)


def limited_by(limits, choice_key, index):
    """A number within +-limits[args[choice_key]][index]: a limit chosen by an earlier field."""
    def check(frame, key, request_id, args):
        return number(limits[args[choice_key]][index])(frame, key, request_id, args)
    return check


def name(frame, key, request_id, _args):
    """A ROS graph name or a model name."""
    value = frame.get(key)
    if not isinstance(value, str) or not NAME_PATTERN.match(value):
        raise ProtocolError("{} must be a name (letters, digits, _ and /, at most 200), got {}".format(
            key, _shown(value, 60)), request_id)
    return value


def name_or_null(frame, key, request_id, args):
    return None if frame.get(key) is None else name(frame, key, request_id, args)


def boolean(frame, key, request_id, _args):
    if not isinstance(frame.get(key), bool):
        raise ProtocolError("{} must be true or false".format(key), request_id)
    return frame[key]


def one_of(choices):
    def check(frame, key, request_id, _args):
        value = frame.get(key)
        if value not in choices:
            raise ProtocolError("{} must be one of {}, got {}".format(key, tuple(choices), _shown(value)), request_id)
        return value
    return check


def field_values(frame, key, request_id, _args):
    """An object of at most MAX_FIELDS name: string | number | boolean pairs (a service request's fields)."""
    fields = frame.get(key, {})
    if not isinstance(fields, dict) or len(fields) > MAX_FIELDS:
        raise ProtocolError("{} must be an object of at most {} name: value pairs".format(key, MAX_FIELDS), request_id)
    for field, value in fields.items():
        if not isinstance(value, (str, int, float, bool)) or (isinstance(value, str) and len(value) > MAX_FIELD_TEXT):
            raise ProtocolError("field {} must be a string (at most {} characters), number or boolean".format(
                field[:40], MAX_FIELD_TEXT), request_id)
    return fields


def _request_id(frame):
    value = frame.get("id")
    if isinstance(value, bool) or not isinstance(value, int) or not 0 <= value < 2 ** 31:
        raise ProtocolError("id must be an integer from 0 to 2^31-1, got {}".format(_shown(value)))
    return value


def parse_command(text, commands):
    """The Command in one text frame, checked against `commands` {type: CommandSpec}.

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
    spec = commands.get(kind) if isinstance(kind, str) else None
    if spec is None:
        raise ProtocolError("unknown type {}".format(_shown(kind)))
    request_id = _request_id(frame) if spec.request else None
    args = {}
    for key, check in spec.fields:
        args[key] = check(frame, key, request_id, args)
    return Command(kind, request_id, args)
