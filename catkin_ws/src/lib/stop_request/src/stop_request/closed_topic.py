"""Publishing from a node that Ctrl-C may be shutting down at that very moment.

rospy closes a node's publishers while its subscriber callbacks and main loop still run, so a publish that
races shutdown raises ROSException("publish() to a closed topic"), and a callback's traceback lands in the
launch output. Seen with learning_tf2's broadcaster: a /turtle1/pose callback in flight when roslaunch
stopped the demo, in one fresh-clone run of the suite. At shutdown the message has nowhere to go, so it is
dropped quietly; any other ROSException is still raised.
"""
import rospy


def publish_unless_shut_down(send, message):
    """`send(message)` (a Publisher's publish, a TransformBroadcaster's sendTransform); False, without
    raising, when rospy shut down and closed the topic before or during the call."""
    try:
        send(message)
    except rospy.ROSException:
        if rospy.is_shutdown():
            return False
        raise
    return True
