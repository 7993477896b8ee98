"""Where `$(find pkg)` points in a ROS 1 workspace.

rospack's rules, through rospkg (the library roslaunch's own `$(find pkg)` uses): the folder holding the package's
package.xml, searched on ROS_PACKAGE_PATH (this workspace's source folders, then Debian's /usr/share). For a
package in the workspace that is its source folder, so a xacro file includes its neighbours where they are edited.
"""
import rospkg


class PackageNotFound(Exception):
    """No package of that name on the ROS package path. str() is the message a user sees."""

    def __init__(self, name):
        super().__init__("package '{}' not found (rospack searched ROS_PACKAGE_PATH)".format(name))
        self.name = name


class PackagePaths:
    """Package name -> folder, crawling the package path once per instance (one xacro run)."""

    def __init__(self, rospack=None):
        self._rospack = rospack if rospack is not None else rospkg.RosPack()

    def find(self, name):
        """The package's folder (str). Raises PackageNotFound."""
        try:
            return self._rospack.get_path(name)
        except rospkg.ResourceNotFound:
            raise PackageNotFound(name) from None
