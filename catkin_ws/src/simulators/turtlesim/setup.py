from catkin_pkg.python_setup import generate_distutils_setup
from setuptools import setup

setup(**generate_distutils_setup(packages=["turtlesim", "turtlesim.core", "turtlesim.ros", "turtlesim.view",
                                           "turtlesim.tools"],
                                 package_dir={"": "src"}))
