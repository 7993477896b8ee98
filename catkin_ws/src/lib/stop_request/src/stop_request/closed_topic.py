"""Publishing from a node that Ctrl-C may be shutting down at that very moment.

rospy closes a node's publishers while its subscriber callbacks and main loop still run, so a publish that
races shutdown raises ROSException("publish() to a closed topic"), and a callback's traceback lands in the
launch output. Seen with learning_tf2's broadcaster: a /turtle1/pose callback in flight when roslaunch
stopped the demo, in fresh-clone runs of the suite. rospy closes the topics in a pre-shutdown hook, before
rospy.is_shutdown() turns true: from the moment shutdown is requested (rospy.core.is_shutdown_requested) the
message has nowhere to go, so it is dropped quietly; any other ROSException is still raised.
"""
import rospy


def shutting_down():
    """True from the moment rospy's shutdown is requested, including the pre-shutdown cleanup that closes the
    topics while rospy.is_shutdown() is still False."""
    return rospy.core.is_shutdown_requested() or rospy.is_shutdown()


def publish_unless_shut_down(send, message):
    """`send(message)` (a Publisher's publish, a TransformBroadcaster's sendTransform); False, without
    raising, when rospy's shutdown closed the topic before or during the call."""
    try:
        send(message)
    except rospy.ROSException:
        if shutting_down():
            return False
        raise
    return True
