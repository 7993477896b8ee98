"""The page <-> server protocol: JSON text frames over one WebSocket (/ws). Every frame has "type".

This module holds what all panels share; each panel (lab_web.panels) documents the frames it sends (FRAMES) and
declares the commands it accepts (COMMANDS, with their schemas), and `document()` gathers them into the whole
protocol, the one place it is written down (`python3 -m lab_web.protocol` prints it).

Server -> page, besides the panels' frames:
  hello  {"version": 1, "panels": [panel name, ...] (the page imports js/panels/<name>.js of each, in this order),
         "world_frame": "map" once a map has come, else "odom", "teleop_limits": {target: [linear m/s, angular
         rad/s]}}   once, on connect
  reply  {"id": the request's id, "ok": bool, "text": what happened}   once per request
  error  {"text": what was wrong with a frame}   for each bad frame, and a command that failed

Page -> server: a command is {"type", field: value, ...}; a request also has "id", an integer from 0 to 2^31-1
that its reply carries back. Frames over lab_web.commands.MAX_FRAME_BYTES are refused unread.
"""
import json
import math

SHARED_FRAMES = {"hello", "reply", "error"}


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


def document(panels):
    """The whole protocol as text: this module's part, then each panel's frames and commands."""
    lines = [__doc__.strip(), ""]
    for panel in panels:
        lines.append("Panel {} ({}):".format(panel.name, panel.__module__))
        for kind, text in panel.FRAMES.items():
            lines.append("  server -> page  {}  {}".format(kind, text))
        for kind, spec in panel.COMMANDS.items():
            fields = ", ".join((["id"] if spec.request else []) + [key for key, _ in spec.fields])
            lines.append("  page -> server  {} {{{}}}  {}{}".format(
                kind, fields, spec.doc,
                "; a request run by the {} workers".format(spec.pool) if spec.request else ""))
        lines.append("")
    return "\n".join(lines)


if __name__ == "__main__":
    from lab_web.panels import PANELS
    print(document(PANELS))
