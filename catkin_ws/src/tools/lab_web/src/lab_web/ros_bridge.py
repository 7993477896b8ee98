"""The web view's ROS side: the server panels (lab_web.panels) over one RosContext, and the master's state read
every GRAPH_PERIOD_S for the panels that follow the graph. It watches the graph through the interfaces any user
has (topics, the master, services) and acts only through them, never inside a simulator."""
import threading

import rosgraph
import rospy

from lab_web.panels import PANELS, command_registry
from lab_web.ros_context import DEFAULT_SERVICE_TIMEOUT_S, GraphState, RosContext

GRAPH_PERIOD_S = 2.0
FIRST_ROUND_RETRY_S = 0.1
"""Until the master first answers, it is asked again this often (the page waits for its first graph)."""
PROTOCOL_VERSION = 1


class RosBridge:
    """Create after rospy.init_node; `shutdown()` stops the panels (teleop sends zero once) and the graph thread.
    `service_timeout_s`: how long a service form call may take before it is abandoned; `use_sim_time`: see
    lab_web.ros_context.RosContext."""

    def __init__(self, robot_namespace="", service_timeout_s=DEFAULT_SERVICE_TIMEOUT_S, panels=PANELS,
                 use_sim_time=False):
        self.ros = RosContext(robot_namespace, service_timeout_s, use_sim_time)
        self.panels = [panel(self.ros) for panel in panels]
        self._by_name = {panel.name: panel for panel in self.panels}
        self.commands = {kind: spec for kind, (_, spec) in command_registry(panels).items()}
        self._panel_of = {kind: self._by_name[name] for kind, (name, _) in command_registry(panels).items()}
        self._stop = threading.Event()
        self._graph_rounds = 0
        self._thread = threading.Thread(target=self._graph_loop, daemon=True, name="lab_web_graph")
        self._thread.start()

    def hello(self):
        content = {"version": PROTOCOL_VERSION, "panels": [panel.name for panel in self.panels]}
        for panel in self.panels:
            content.update(panel.hello())
        return content

    def handle(self, session, command):
        """Run a parsed command in the panel that declared it (a request's reply text, or None)."""
        return self._panel_of[command.type].handle(session, command.type, command.args)

    def _graph_loop(self):
        master = rosgraph.Master(rospy.get_name())
        while not self._stop.wait(GRAPH_PERIOD_S if self._graph_rounds else FIRST_ROUND_RETRY_S):
            try:
                publishers, subscribers, services = master.getSystemState()
                graph = GraphState(publishers, subscribers, services, dict(master.getTopicTypes()))
            except (OSError, rosgraph.MasterException):
                continue   # the master is restarting: the next round will see it
            self._graph_rounds += 1
            for panel in self.panels:
                panel.on_graph(graph)

    def disconnect(self, owner):
        """Page `owner` went away: stop what it drove, drop what it asked for."""
        for panel in self.panels:
            panel.disconnect(owner)

    def shutdown(self):
        for panel in self.panels:
            panel.shutdown()
        self._stop.set()
