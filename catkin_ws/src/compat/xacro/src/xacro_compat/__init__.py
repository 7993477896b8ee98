"""ROS 1's `xacro` command on top of the PyPI xacro release: `$(find pkg)` through the ROS package path."""
from xacro_compat.command import main, use_package_path
from xacro_compat.package_path import PackageNotFound, PackagePaths

__all__ = ["PackageNotFound", "PackagePaths", "main", "use_package_path"]
