#!/usr/bin/env python3
"""Set another node's my_parameter or your_parameter through the parameter server (the ROS 1 way: the
node reads it back on its next log tick). The value is read as YAML, as `rosparam set` does.

usage: rosrun python_parameters set_parameters_client <my_parameter|your_parameter> <value> [node]
"""
import sys

import rospy
import yaml

PARAMETERS = ("my_parameter", "your_parameter")
DEFAULT_NODE = "/minimal_param_node"
USAGE = "usage: rosrun python_parameters set_parameters_client <{}> <value> [node]".format("|".join(PARAMETERS))

if __name__ == "__main__":
    arguments = rospy.myargv(sys.argv)[1:]
    if len(arguments) not in (2, 3) or arguments[0] not in PARAMETERS:
        print(USAGE, file=sys.stderr)
        sys.exit(1)
    name, text = arguments[:2]
    node = arguments[2] if len(arguments) == 3 else DEFAULT_NODE
    try:
        value = yaml.safe_load(text)
    except yaml.YAMLError:
        value = text
    rospy.init_node("set_parameters_client", anonymous=True)
    key = rospy.names.ns_join(node, name)
    rospy.set_param(key, value)
    print("{} = {}".format(key, rospy.get_param(key)))
