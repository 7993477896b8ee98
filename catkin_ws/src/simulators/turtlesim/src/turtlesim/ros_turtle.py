"""The ROS interfaces of one turtle (imports rospy): what roscpp's Turtle object advertises.

All names are relative to the node's namespace and use the turtle's name unchanged as their
namespace: <name>/cmd_vel (geometry_msgs/Twist, subscribed), <name>/pose (turtlesim/Pose) and
<name>/color_sensor (turtlesim/Color), published once per tick, queue 1, not latched; services
<name>/set_pen, <name>/teleport_absolute and <name>/teleport_relative.
"""
import functools

import rospy
from geometry_msgs.msg import Twist

from .msg import Color, Pose
from .ros_service import RoscppStyleService
from .srv import SetPen, TeleportAbsolute, TeleportRelative


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
        self._services = [
            RoscppStyleService(name + '/set_pen', SetPen,
                               functools.partial(handlers.set_pen, name)),
            RoscppStyleService(name + '/teleport_relative', TeleportRelative,
                               functools.partial(handlers.teleport_relative, name)),
            RoscppStyleService(name + '/teleport_absolute', TeleportAbsolute,
                               functools.partial(handlers.teleport_absolute, name)),
        ]

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
