#!/usr/bin/env python3
"""params_demo.py: sets, reads back and deletes parameters on the parameter server, printing each step.

It uses a global, a relative and a private name (see beginner_tutorials/parameters.py), reads a missing one
with a default, and deletes everything it set, so it leaves the parameter server as it found it.
"""
import rospy

from beginner_tutorials.parameters import DEMO_PARAMETERS, MISSING_DEFAULT, MISSING_NAME


class ParamsDemo:
    def set_all(self):
        for parameter in DEMO_PARAMETERS:
            rospy.set_param(parameter.name, parameter.value)
            print("set    {:<8} {} ({}) = {!r}".format(parameter.kind, parameter.name,
                                                       rospy.resolve_name(parameter.name), parameter.value))

    def get_all(self):
        for parameter in DEMO_PARAMETERS:
            print("get    {} -> {!r}".format(parameter.name, rospy.get_param(parameter.name)))
        print("get    {} (default {!r}) -> {!r}".format(MISSING_NAME, MISSING_DEFAULT,
                                                        rospy.get_param(MISSING_NAME, MISSING_DEFAULT)))

    def delete_all(self):
        for parameter in DEMO_PARAMETERS:
            rospy.delete_param(parameter.name)
            print("delete {} -> still there: {}".format(parameter.name, rospy.has_param(parameter.name)))


def main():
    rospy.init_node("params_demo")
    demo = ParamsDemo()
    demo.set_all()
    demo.get_all()
    demo.delete_all()


if __name__ == "__main__":
    main()
