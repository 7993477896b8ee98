"""What every panel is: the server half of one thing the page shows (the page half is static/js/panels/<name>.js).
No ROS import here.

A panel subscribes to what it shows, keeps it as Versioned values, and each page's session asks it for the
frames that page lacks (`frames`); it documents its frames (FRAMES) and declares the commands it accepts
(COMMANDS, lab_web.commands.CommandSpec), which the server dispatches to `handle`.
"""
from typing import Dict


class Versioned:
    """A value and a counter that goes up with each change, so each page sends only what is new to it."""

    def __init__(self, value=None):
        self.value, self.version = value, 0

    def set(self, value):
        self.value, self.version = value, self.version + 1


class Panel:
    """Base of the server panels. `ros` is the lab_web.ros_context.RosContext they share (names in the robot's
    namespace, rates, services with a timeout)."""

    name = ""
    FRAMES: Dict[str, str] = {}
    """Frame type -> its content and when it is sent (the protocol's documentation)."""
    COMMANDS: Dict[str, object] = {}
    """Command type -> lab_web.commands.CommandSpec."""

    def __init__(self, ros):
        self.ros = ros

    def hello(self):
        """What this panel adds to the `hello` frame."""
        return {}

    def frames(self, session):
        """(type, content) of each frame page `session` lacks now (session.lacks tells what is new to it)."""
        return []

    @staticmethod
    def lacking(session, *versioned_frames):
        """(type, content) of each (frame type, Versioned content[, key]) whose content page `session` lacks; the
        key (the frame type when not given) names what the page was sent, for two frames of one type."""
        out = []
        for kind, versioned, *key in versioned_frames:
            content = session.lacks(key[0] if key else kind, versioned)
            if content is not None:
                out.append((kind, content))
        return out

    def handle(self, session, kind, args):
        """Run command `kind` for page `session`; a request's result is the text of its reply, an exception a
        failed reply. Requests run in worker threads, other commands in the event loop's executor or at once."""
        raise NotImplementedError(kind)

    def on_graph(self, graph):
        """Every GRAPH_PERIOD_S: the master's state (lab_web.ros_context.GraphState)."""

    def disconnect(self, owner):
        """Page `owner` went away."""

    def shutdown(self):
        """The server is stopping."""
