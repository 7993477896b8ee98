"""What a page may send: every command type parsed, and every kind of bad frame refused with a reason that names
the problem (never an exception other than ProtocolError)."""
import json
import math
import re
from pathlib import Path

import pytest

from lab_web.commands import MAX_FRAME_BYTES, CommandSpec, ProtocolError, parse_command
from lab_web.panels import PANELS, command_registry, panel_class
from lab_web.protocol import document, frame

STATIC_DIR = Path(__file__).resolve().parents[3] / "catkin_ws" / "src" / "tools" / "lab_web" / "static"
COMMANDS = {kind: spec for kind, (_, spec) in command_registry().items()}


def parse(content):
    return parse_command(json.dumps(content), COMMANDS)


def refusal(text):
    with pytest.raises(ProtocolError) as error:
        parse_command(text, COMMANDS)
    return error.value


def test_teleop_within_the_limits_is_accepted():
    command = parse({"type": "teleop", "target": "robot", "linear": 0.2, "angular": -1.5})
    assert command == ("teleop", None, {"target": "robot", "linear": 0.2, "angular": -1.5})


@pytest.mark.parametrize("content, named", [
    ({"type": "teleop", "target": "robot", "linear": 0.27, "angular": 0}, "linear"),
    ({"type": "teleop", "target": "robot", "linear": 0, "angular": 1.9}, "angular"),
    ({"type": "teleop", "target": "turtle1", "linear": 1e308, "angular": 0}, "linear"),
    ({"type": "teleop", "target": "robot", "linear": "fast", "angular": 0}, "linear"),
    ({"type": "teleop", "target": "robot", "linear": True, "angular": 0}, "linear"),
    ({"type": "teleop", "target": "robot", "angular": 0}, "linear"),
    ({"type": "teleop", "target": "tank", "linear": 0, "angular": 0}, "target"),
])
def test_bad_teleop_is_refused_naming_the_field(content, named):
    assert str(refusal(json.dumps(content))).startswith(named)


def test_non_finite_numbers_are_refused():
    # Python's json accepts NaN and Infinity tokens, which no browser sends
    assert "finite" in str(refusal('{"type": "teleop", "target": "robot", "linear": NaN, "angular": 0}'))
    assert "finite" in str(refusal('{"type": "spawn_box", "id": 1, "x": Infinity, "y": 0}'))


@pytest.mark.parametrize("kind", ["teleop", "spawn_box"])
def test_an_integer_too_large_for_a_float_is_refused_not_a_crash(kind):
    """A 309-digit integer is valid JSON that float() cannot hold: it used to raise OverflowError and drop the
    page."""
    huge = "1" + "0" * 308
    text = ('{"type": "teleop", "target": "robot", "linear": %s, "angular": 0}' % huge if kind == "teleop" else
            '{"type": "spawn_box", "id": 1, "x": %s, "y": 0}' % huge)
    reason = str(refusal(text))
    assert "must be a finite number within" in reason and "1000000000" in reason


@pytest.mark.parametrize("text, reason", [
    ("", "not JSON"), ("{", "not JSON"), ("[1, 2]", "JSON object"), ('"teleop"', "JSON object"),
    ('{"type": "launch_missiles"}', "unknown type"), ("{}", "unknown type"),
    ('{"type": "spawn_box", "x": 1, "y": 1}', "id must be"), ('{"type": "reset_world", "id": -1}', "id must be"),
    ('{"type": "reset_world", "id": true}', "id must be"), ('{"type": "camera", "on": 1}', "on must be"),
    ('{"type": "delete_model", "id": 3, "name": "a b"}', "name must be"),
    ('{"type": "echo", "topic": "/odom; rm -rf /"}', "topic must be"),
])
def test_malformed_frames_are_refused_with_a_reason(text, reason):
    assert reason in str(refusal(text))


def test_a_refused_request_keeps_its_id_for_the_reply():
    assert refusal('{"type": "move_model", "id": 7, "name": "box", "x": "left", "y": 0}').request_id == 7


def test_oversized_frames_are_refused_before_parsing():
    assert "too large" in str(refusal(" " * (MAX_FRAME_BYTES + 1)))


def test_requests_carry_their_arguments():
    assert parse({"type": "spawn_box", "id": 4, "x": 1, "y": -2.5}) == ("spawn_box", 4, {"x": 1.0, "y": -2.5})
    assert parse({"type": "call_service", "id": 5, "service": "/move_service", "fields": {"request_signal": True}}) \
        == ("call_service", 5, {"service": "/move_service", "fields": {"request_signal": True}})
    assert parse({"type": "echo", "topic": None}).args == {"topic": None}


def test_call_service_fields_must_be_plain_values():
    assert "fields" in str(refusal(json.dumps({"type": "call_service", "id": 1, "service": "/s", "fields": [1]})))
    assert "field a" in str(refusal(json.dumps({"type": "call_service", "id": 1, "service": "/s",
                                                "fields": {"a": {"nested": 1}}})))


def test_server_frames_are_json_without_non_finite_numbers():
    text = frame("state", rtf=math.inf, scan=[[1.0, math.nan]])
    assert json.loads(text) == {"type": "state", "rtf": None, "scan": [[1.0, None]]}


def test_deeply_nested_json_is_refused_not_a_crash():
    assert "nested too deeply" in str(refusal("[" * 4000))


def test_every_command_is_declared_once_and_documented():
    assert set(COMMANDS) == {"teleop", "spawn_box", "move_model", "delete_model", "reset_world", "service_fields",
                             "call_service", "echo", "camera", "initial_pose", "nav_goal", "publish_point",
                             "cancel_goal", "save_map", "pick_robot"}
    text = document(PANELS)
    for kind, spec in COMMANDS.items():
        assert spec.doc and "page -> server  {} {{".format(kind) in text
    for panel in PANELS:
        for kind in panel.FRAMES:
            assert "server -> page  {}  ".format(kind) in text


def test_every_server_panel_has_its_page_module_and_app_js_lists_none():
    """The page imports js/panels/<name>.js for each name `hello` gives: the server's list is the only one."""
    static = STATIC_DIR
    for panel in PANELS:
        assert re.fullmatch(r"[a-z][a-z0-9_]*", panel.name), panel.name
        module = (static / "js" / "panels" / "{}.js".format(panel.name)).read_text()
        assert "export default {{name: '{}'".format(panel.name) in module.replace("\n  ", "")
    assert "js/panels/" in (static / "app.js").read_text()
    assert not re.search(r"import \w+ from './js/panels/", (static / "app.js").read_text())


def test_a_panel_module_without_its_named_panel_class_is_an_error_naming_it():
    with pytest.raises(ImportError, match="lab_web.panels.base must define one Panel subclass named 'base', found 0"):
        panel_class("base")


def test_a_command_declared_by_two_panels_is_refused_at_start():
    class First:
        name, COMMANDS = "first", {"go": CommandSpec((), "go")}

    class Second(First):
        name = "second"
    with pytest.raises(ValueError, match="go is declared by panels first and second"):
        command_registry((First, Second))


@pytest.mark.parametrize("content, named", [
    ({"type": "initial_pose", "frame": "map", "x": 1, "y": 2, "yaw": 4}, "yaw"),
    ({"type": "nav_goal", "frame": "map; rm", "x": 1, "y": 2, "yaw": 0}, "frame"),
    ({"type": "publish_point", "frame": "map", "x": 1e9, "y": 0}, "x"),
    ({"type": "save_map", "id": 1, "folder": "..", "name": "m"}, "folder"),
    ({"type": "save_map", "id": 1, "folder": "maps", "name": "a/b"}, "name"),
])
def test_tool_commands_are_validated_like_the_others(content, named):
    assert str(refusal(json.dumps(content))).startswith(named)


def test_a_tool_command_carries_its_pose():
    assert parse({"type": "nav_goal", "frame": "map", "x": 1, "y": -2, "yaw": 3.0}) == (
        "nav_goal", None, {"frame": "map", "x": 1.0, "y": -2.0, "yaw": 3.0})
