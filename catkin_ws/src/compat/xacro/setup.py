from catkin_pkg.python_setup import generate_distutils_setup
from setuptools import setup

# The module is not called `xacro`: that name belongs to the PyPI package this one wraps.
setup(**generate_distutils_setup(packages=["xacro_compat"], package_dir={"": "src"}))
