#!/usr/bin/env python3
"""Print another node's my_parameter and your_parameter from the parameter server.

usage: rosrun python_parameters get_parameters_client [node]     (node defaults to /minimal_param_node)
"""
import sys

import rospy

PARAMETERS = ("my_parameter", "your_parameter")
DEFAULT_NODE = "/minimal_param_node"

if __name__ == "__main__":
    arguments = rospy.myargv(sys.argv)[1:]
    node = arguments[0] if arguments else DEFAULT_NODE
    rospy.init_node("get_parameters_client", anonymous=True)
    for name in PARAMETERS:
        key = rospy.names.ns_join(node, name)
        if not rospy.has_param(key):
            print("No parameter {}: is {} running?".format(key, node), file=sys.stderr)
            sys.exit(1)
        print("{} = {}".format(key, rospy.get_param(key)))
