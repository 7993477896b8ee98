"""Waiting politely for a service: a log line every second while it is missing, never a crash or a hang
that ignores Ctrl-C."""
import rospy

WAIT_SLICE_S = 1.0


def wait_politely(service_name):
    """Block until `service_name` exists, logging 'service not available, waiting again...' each second
    (the course's wording). Raises rospy.ROSInterruptException on shutdown."""
    while not rospy.is_shutdown():
        try:
            rospy.wait_for_service(service_name, WAIT_SLICE_S)
            return
        except rospy.ROSException:
            rospy.loginfo("service %s not available, waiting again...", service_name)
    raise rospy.ROSInterruptException("shut down while waiting for " + service_name)
