"""The robots panel: the robots running (each namespace that publishes nav_msgs/Odometry on <ns>/odom, as
tb3_sim's and Gazebo's TurtleBot3s do: multi_turtlebot3.launch's /tb3_0, /tb3_1, /tb3_2) and which one lab_web
shows and drives. Picking one moves the robot, trail, LiDAR, camera and teleop panels to its namespace for every
open page (one robot at a time, as one RViz window follows the robot whose topics its displays name); the map and
navigation displays move to the robot's own topics where it has them (/tb3_0/map, /tb3_0/particlecloud, ...), else
stay on the global ones a single stack uses. No ROS import."""
import threading

from lab_web import commands
from lab_web.panels.base import Panel, Versioned
from lab_web.ros_context import canonical_namespace

ODOMETRY_TYPE = "nav_msgs/Odometry"
ODOM = "/odom"


def robot_namespaces(publishers, topic_types):
    """The sorted namespaces ("/" for the global one) with a publisher of nav_msgs/Odometry on <ns>/odom."""
    found = set()
    for topic, nodes in publishers:
        if nodes and topic.endswith(ODOM) and topic_types.get(topic) == ODOMETRY_TYPE:
            found.add(topic[:-len(ODOM)] or "/")
    return sorted(found)


def namespace(frame, key, request_id, _args):
    """"/" (the global namespace) or a graph name."""
    if frame.get(key) == "/":
        return "/"
    return "/" + commands.name(frame, key, request_id, _args).strip("/")


class RobotsPanel(Panel):
    name = "robots"
    FRAMES = {"robots": '{"robots": [namespace, ...] ("/": the global one), "picked": the namespace shown and '
                        'driven}  on connect and when either changes (the master is read every 2 s)'}
    COMMANDS = {"pick_robot": commands.CommandSpec(
        (("namespace", namespace),),
        "show and drive the robot in namespace (one of the robots frame's) on every page; refused for a namespace "
        "with no robot")}

    def __init__(self, ros):
        super().__init__(ros)
        self._lock = threading.Lock()
        self._robots = []
        self.robots = Versioned({"robots": [], "picked": self._picked()})

    def _picked(self):
        return self.ros.namespace or "/"

    def frames(self, session):
        return self.lacking(session, ("robots", self.robots))

    def on_graph(self, graph):
        robots = robot_namespaces(graph.publishers, graph.topic_types)
        with self._lock:
            self._robots = robots
            self._update()

    def _update(self):
        content = {"robots": self._robots, "picked": self._picked()}
        if content != self.robots.value:
            self.robots.set(content)

    def handle(self, session, kind, args):
        with self._lock:
            if args["namespace"] not in self._robots:
                raise ValueError("no robot publishes {}/odom; the robots are {}".format(
                    canonical_namespace(args["namespace"]), ", ".join(self._robots) or "none yet"))
        self.ros.pick_robot(args["namespace"])
        with self._lock:
            self._update()
