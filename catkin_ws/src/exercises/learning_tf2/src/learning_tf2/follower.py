"""The tf2 tutorial's listener: spawn a follower turtle and steer it toward a target frame at 10 Hz.

Where the target is looked up (now, or in the past) is a strategy passed in, so the tutorial's "time travel"
variants are the same node with a different lookup (see LOOKUPS). Until the frames exist the node waits
politely: one throttled log line, no exception, no motion.
"""
import rospy
import tf2_ros
from geometry_msgs.msg import Twist

from learning_tf2.follow import follow_command
from learning_tf2.ros_frames import LOOKUP_ERRORS, log_waiting
from stop_request.closed_topic import publish_unless_shut_down
from turtlesim.srv import Spawn

CONTROL_RATE_HZ = 10
FOLLOWER_SPAWN_POSE = (4.0, 2.0, 0.0)
HISTORY_S = 5.0
LOOKUP_TIMEOUT_S = 1.0


def latest(buffer, follower, target):
    """The target now, in the follower's frame now (the basic tutorial)."""
    return buffer.lookup_transform(follower, target, rospy.Time())


def five_seconds_ago(buffer, follower, target):
    """Time travel, first try: the target 5 s ago relative to where the follower was 5 s ago."""
    past = rospy.Time.now() - rospy.Duration(HISTORY_S)
    return buffer.lookup_transform(follower, target, past, rospy.Duration(LOOKUP_TIMEOUT_S))


def five_seconds_ago_from_now(buffer, follower, target):
    """Time travel done right: where the target was 5 s ago, relative to the follower now, through `world`."""
    now = rospy.Time.now()
    past = now - rospy.Duration(HISTORY_S)
    return buffer.lookup_transform_full(follower, now, target, past, "world", rospy.Duration(LOOKUP_TIMEOUT_S))


LOOKUPS = {"latest": latest, "then": five_seconds_ago, "now": five_seconds_ago_from_now}


class TurtleFollower:
    """Spawns `follower` (unless it exists) and drives it toward `target` using `lookup`."""

    def __init__(self, follower, target, lookup):
        self.follower, self.target, self.lookup = follower, target, lookup
        self.buffer = tf2_ros.Buffer()
        self.listener = tf2_ros.TransformListener(self.buffer)
        self.spawn_follower()
        self.cmd_vel = rospy.Publisher("{}/cmd_vel".format(self.follower), Twist, queue_size=1)

    def spawn_follower(self):
        rospy.wait_for_service("spawn")
        try:
            rospy.ServiceProxy("spawn", Spawn)(*FOLLOWER_SPAWN_POSE, self.follower)
        except rospy.ServiceException:
            rospy.loginfo("Could not spawn '%s' (it probably exists already): following with it.", self.follower)

    def step(self):
        try:
            seen = self.lookup(self.buffer, self.follower, self.target).transform.translation
        except LOOKUP_ERRORS as error:
            log_waiting(error)
            return
        command = follow_command(seen.x, seen.y)
        twist = Twist()
        twist.linear.x, twist.angular.z = command.linear, command.angular
        publish_unless_shut_down(self.cmd_vel.publish, twist)

    def run(self):
        rate = rospy.Rate(CONTROL_RATE_HZ)
        while not rospy.is_shutdown():
            self.step()
            try:
                rate.sleep()
            except rospy.ROSTimeMovedBackwardsException:
                self.buffer.clear()


def main(lookup_name="latest"):
    """Node entry point. Private params: ~follower (turtle2), ~target_frame (turtle1)."""
    rospy.init_node("tf2_turtle_listener")
    follower = rospy.get_param("~follower", "turtle2")
    target = rospy.get_param("~target_frame", "turtle1")
    try:
        TurtleFollower(follower, target, LOOKUPS[lookup_name]).run()
    except rospy.ROSInterruptException:
        pass
