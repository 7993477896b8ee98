"""The server panels, in the order their frames go to a page. Adding a panel: a module here with a Panel subclass,
its page module static/js/panels/<name>.js (the page imports the modules the `hello` frame names, in this order),
and one line in PANELS."""
from lab_web.panels.camera import CameraPanel
from lab_web.panels.drive import DrivePanel
from lab_web.panels.graph import GraphPanel
from lab_web.panels.map import MapPanel
from lab_web.panels.nav import NavPanel
from lab_web.panels.robot import RobotPanel
from lab_web.panels.robots import RobotsPanel
from lab_web.panels.save_map import SaveMapPanel
from lab_web.panels.services import ServicesPanel
from lab_web.panels.tools import ToolsPanel
from lab_web.panels.turtlesim import TurtlesimPanel
from lab_web.panels.world import WorldPanel

PANELS = (
    WorldPanel,
    MapPanel,
    NavPanel,
    RobotPanel,
    RobotsPanel,
    TurtlesimPanel,
    GraphPanel,
    CameraPanel,
    DrivePanel,
    ServicesPanel,
    ToolsPanel,
    SaveMapPanel,
)


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
