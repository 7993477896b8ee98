"""The server panels, in the order their frames go to a page.

Adding a panel `<name>`: its server module lab_web/panels/<name>.py with one Panel subclass whose `name` is
"<name>", its page module static/js/panels/<name>.js (the page imports the modules the `hello` frame names, in this
order), and "<name>" in PANEL_NAMES: one line."""
import importlib
import inspect

from lab_web.panels.base import Panel

PANEL_NAMES = (
    "world",
    "map",
    "nav",
    "robot",
    "robots",
    "turtlesim",
    "graph",
    "camera",
    "drive",
    "services",
    "tools",
    "save_map",
)


def panel_class(name):
    """The Panel subclass of module lab_web.panels.<name>, the one whose `name` is `name`."""
    module = importlib.import_module("lab_web.panels." + name)
    found = [cls for _, cls in inspect.getmembers(module, inspect.isclass)
             if issubclass(cls, Panel) and cls.__module__ == module.__name__ and cls.name == name]
    if len(found) != 1:
        raise ImportError("lab_web.panels.{} must define one Panel subclass named {!r}, found {}".format(
            name, name, len(found)))
    return found[0]


PANELS = tuple(panel_class(name) for name in PANEL_NAMES)


def command_registry(panels=PANELS):
    """{command type: (panel name, CommandSpec)} of `panels`; a type declared twice is a programming error."""
    registry = {}
    for panel in panels:
        for kind, spec in panel.COMMANDS.items():
            if kind in registry:
                raise ValueError("command {} is declared by panels {} and {}".format(kind, registry[kind][0],
                                                                                    panel.name))
            registry[kind] = (panel.name, spec)
    return registry
