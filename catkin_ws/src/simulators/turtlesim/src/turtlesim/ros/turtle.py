"""The ROS interfaces of one turtle (imports rospy): what roscpp's Turtle object advertises.

All names are relative to the node's namespace and use the turtle's name unchanged as their
namespace: <name>/cmd_vel (geometry_msgs/Twist, subscribed), <name>/pose (turtlesim/Pose) and
<name>/color_sensor (turtlesim/Color), published once per tick, queue 1, not latched; services
<name>/set_pen, <name>/teleport_absolute and <name>/teleport_relative.

Two turtles can map to the same names (e.g. `turtle1` and `/turtle1` in the root namespace).
As in roscpp, they then share the topics, and a service this node already offers is not
advertised again: ERROR `Tried to advertise a service that is already advertised in this node
[<name>]`, and the turtle lives on without it.
"""
import functools

import rospy
from geometry_msgs.msg import Twist

from turtlesim.msg import Color, Pose
from turtlesim.ros.service import RoscppStyleService
from turtlesim.srv import SetPen, TeleportAbsolute, TeleportRelative

ALREADY_ADVERTISED_LOG = 'Tried to advertise a service that is already advertised in this node [%s]'
"""roscpp's ERROR text when a node advertises a service name twice."""


def advertise(name, service_class, handler):
    """A RoscppStyleService, or None (ERROR logged) when this node already offers `name`."""
    try:
        return RoscppStyleService(name, service_class, handler)
    except rospy.ServiceException:
        rospy.logerr(ALREADY_ADVERTISED_LOG % rospy.resolve_name(name))
        return None


class TurtleInterfaces:
    """Publishers, subscriber and services of turtle `name`, wired to `handlers`.

    `handlers` provides on_cmd_vel(twist, name) and set_pen / teleport_absolute /
    teleport_relative(name, request) returning the service responses.
    """

    def __init__(self, name, handlers):
        self.name = name
        self._pose = rospy.Publisher(name + '/pose', Pose, queue_size=1)
        self._color = rospy.Publisher(name + '/color_sensor', Color, queue_size=1)
        self._cmd_vel = rospy.Subscriber(name + '/cmd_vel', Twist, handlers.on_cmd_vel,
                                         callback_args=name, queue_size=1)
        services = [
            advertise(name + '/set_pen', SetPen, functools.partial(handlers.set_pen, name)),
            advertise(name + '/teleport_relative', TeleportRelative,
                      functools.partial(handlers.teleport_relative, name)),
            advertise(name + '/teleport_absolute', TeleportAbsolute,
                      functools.partial(handlers.teleport_absolute, name)),
        ]
        self._services = [service for service in services if service is not None]

    def publish(self, tick_result):
        """Publish one tick's pose, then its color_sensor reading (a core TickResult)."""
        self._pose.publish(Pose(*tick_result.pose))
        self._color.publish(Color(*tick_result.color))

    def shutdown(self):
        """Withdraw every interface of this turtle from the graph (it was killed or reset)."""
        self._cmd_vel.unregister()
        self._pose.unregister()
        self._color.unregister()
        for service in self._services:
            service.shutdown('turtle [%s] removed' % self.name)
