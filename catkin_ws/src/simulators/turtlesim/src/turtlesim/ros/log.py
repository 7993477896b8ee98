"""The core's log sink for ROS nodes (imports rospy): LogLevel to rospy's loggers."""
import rospy

from turtlesim.core.log import LogLevel

ROS_LOGGERS = {LogLevel.INFO: rospy.loginfo, LogLevel.WARN: rospy.logwarn,
               LogLevel.ERROR: rospy.logerr}


def ros_log(level, text):
    """LogSink: INFO/WARN/ERROR text to rospy.loginfo/logwarn/logerr (console and /rosout)."""
    ROS_LOGGERS[level](text)
