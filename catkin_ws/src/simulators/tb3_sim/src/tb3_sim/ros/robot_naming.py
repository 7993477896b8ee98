"""Where a robot's topics and TF frames live, as Gazebo's ROS plugins name them.

A robot spawned with a `robot_namespace` (spawn_model takes the namespace it runs in, so a spawn inside
`<group ns="tb3_0">` gives "/tb3_0/") publishes /tb3_0/odom, /tb3_0/scan, ... and subscribes /tb3_0/cmd_vel.
Its frames carry a tf_prefix, as gazebo_ros's plugins resolve them: the `tf_prefix` parameter found by searching
up from the namespace, else the namespace itself without slashes (so "tb3_0/odom", "tb3_0/base_footprint",
"tb3_0/base_scan"); a robot in the root namespace has no prefix.
"""

from dataclasses import dataclass

SEPARATOR = "/"


@dataclass(frozen=True)
class RobotNaming:
    """`namespace`: "" for names relative to the node's own namespace (the robot the node starts with, as the
    plugins of a robot spawned next to gzserver), or an absolute namespace ending in "/"; `tf_prefix`: "" or a
    prefix without slashes at either end."""

    namespace: str = ""
    tf_prefix: str = ""

    def topic(self, name):
        """The robot's topic `name` (e.g. "odom")."""
        return self.namespace + name

    def frame(self, name):
        """The robot's TF frame `name` (e.g. "base_footprint") with its prefix."""
        return f"{self.tf_prefix}{SEPARATOR}{name}" if self.tf_prefix else name

    def transforms(self, transforms):
        """(parent, child, xyz, rpy) fixed joints with both frames prefixed."""
        return tuple((self.frame(parent), self.frame(child), xyz, rpy) for parent, child, xyz, rpy in transforms)


def absolute_namespace(namespace):
    """A spawn request's robot_namespace as an absolute namespace: "" and "/" are the root "/", "tb3_0" and
    "/tb3_0" are "/tb3_0/"."""
    parts = [part for part in namespace.split(SEPARATOR) if part]
    return SEPARATOR + "".join(part + SEPARATOR for part in parts)


def spawned_robot_naming(namespace, tf_prefix_param=None):
    """The RobotNaming of a robot spawned into `namespace` (a request's robot_namespace); `tf_prefix_param` is the
    value of the tf_prefix parameter found from that namespace (None or empty: there is none)."""
    namespace = absolute_namespace(namespace)
    prefix = str(tf_prefix_param) if tf_prefix_param else namespace
    return RobotNaming(namespace, prefix.strip(SEPARATOR))
