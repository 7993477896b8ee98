from catkin_pkg.python_setup import generate_distutils_setup
from setuptools import setup

setup(**generate_distutils_setup(packages=["tb3_sim", "tb3_sim.core", "tb3_sim.ros", "tb3_sim.view", "tb3_sim.tools"],
                                 package_dir={"": "src"}))
