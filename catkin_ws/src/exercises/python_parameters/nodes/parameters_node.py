#!/usr/bin/env python3
"""A node with two private parameters, ~my_parameter ("world") and ~your_parameter ("ros"), that logs both
every second. Change them from anywhere with the parameter server (set_parameters_client.py or
`rosparam set /minimal_param_node/my_parameter earth`): the next log line shows the new value."""
import rospy

DEFAULTS = {"my_parameter": "world", "your_parameter": "ros"}
LOG_PERIOD_S = 1.0


class ParametersNode:
    def __init__(self):
        for name, default in DEFAULTS.items():
            if not rospy.has_param("~" + name):
                rospy.set_param("~" + name, default)
        self.timer = rospy.Timer(rospy.Duration(LOG_PERIOD_S), self.log_parameters)

    def log_parameters(self, event):
        values = {name: rospy.get_param("~" + name, default) for name, default in DEFAULTS.items()}
        rospy.loginfo("my_parameter: %s, your_parameter: %s", values["my_parameter"], values["your_parameter"])


if __name__ == "__main__":
    rospy.init_node("minimal_param_node")
    ParametersNode()
    rospy.spin()
