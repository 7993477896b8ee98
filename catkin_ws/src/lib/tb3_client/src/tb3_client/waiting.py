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


def call_once(service_name, service_class, done_message):
    """Wait politely for `service_name`, call it once with an empty request and log `done_message`; a
    failed call or Ctrl-C while waiting is logged as an error instead of a traceback."""
    try:
        wait_politely(service_name)
        rospy.ServiceProxy(service_name, service_class)()
        rospy.loginfo(done_message)
    except (rospy.ROSInterruptException, rospy.ServiceException) as error:
        rospy.logerr("could not call %s: %s", service_name, error)
