"""turtlebot3_drive (imports rospy): the obstacle-avoidance demo's node, wiring ObstacleAvoider to the robot.

Node name `turtlebot3_drive` (turtlebot3_simulation.launch names it `$(arg name)_drive`).
- Subscribes `scan` (sensor_msgs/LaserScan) and `odom` (nav_msgs/Odometry, for the heading), queue 10 each.
- Publishes geometry_msgs/Twist (queue 10) on the topic named by the parameter `cmd_vel_topic_name`, read
  relative to the node's namespace as the original does (the launch file sets `/cmd_vel_topic_name` from its
  `cmd_vel` arg); `cmd_vel` in the node's namespace if the parameter is absent. A value that is not a legal,
  non-empty topic name ends the node with one clear line and exit code 1.
- Every 1/125 s of ROS time (simulated under /use_sim_time, so the demo keeps its behaviour when the simulator
  runs faster or slower than real time) it makes one decision with the latest readings and publishes what the
  ObstacleAvoider returns. Nothing is decided before the first scan and odometry have arrived.
- A scan with too few beams is reported (at most every 10 s) and the robot is stopped until a usable one comes.
- Ctrl-C or SIGTERM (roslaunch ending it), `rosnode kill` or any other shutdown: it publishes one zero Twist
  as its last command, so the robot stops, and gives it time to reach the robot before rospy tears the node
  down (tb3_client.commands). The signals are handled by stop_request, from a thread of their own: the
  loop publishes hundreds of times per wall second, and rospy's handler, publishing on top of it, deadlocked.
The control loop survives /gazebo/reset_simulation (ROS time going back).
"""
import rosgraph.names
import rospy
from nav_msgs.msg import Odometry
from sensor_msgs.msg import LaserScan

from stop_request import StopRequest
from tb3_client.commands import CommandPublisher
from turtlebot3_gazebo.obstacle_avoider import (
    CONTROL_RATE_HZ,
    STOP,
    DriveError,
    ObstacleAvoider,
    heading_from_quaternion,
    ranges_from_scan,
)

NODE_NAME = "turtlebot3_drive"
CMD_VEL_PARAM = "cmd_vel_topic_name"
DEFAULT_CMD_VEL_TOPIC = "cmd_vel"
QUEUE_SIZE = 10
BAD_SCAN_LOG_PERIOD_S = 10.0


class DriveNode:
    """Latest /scan ranges and /odom heading in, the avoider's commands out on `cmd_vel_topic`."""

    def __init__(self, cmd_vel_topic):
        self._avoider = ObstacleAvoider()
        self._ranges = None
        self._heading = None
        self._last_command = None
        self._cmd_vel = CommandPublisher(cmd_vel_topic, queue_size=QUEUE_SIZE)
        self._scan_sub = rospy.Subscriber("scan", LaserScan, self._on_scan, queue_size=QUEUE_SIZE)
        self._odom_sub = rospy.Subscriber("odom", Odometry, self._on_odom, queue_size=QUEUE_SIZE)
        rospy.on_shutdown(self.stop_for_good)

    def _on_scan(self, scan):
        try:
            self._ranges = ranges_from_scan(scan.ranges, scan.range_max)
        except DriveError as error:
            self._ranges = None
            rospy.logerr_throttle(BAD_SCAN_LOG_PERIOD_S, "%s: ignoring %s: %s", NODE_NAME,
                                  self._scan_sub.resolved_name, error)

    def _on_odom(self, odom):
        q = odom.pose.pose.orientation
        self._heading = heading_from_quaternion(q.x, q.y, q.z, q.w)

    def tick(self):
        """One control tick: decide with the latest readings and publish the command, if any."""
        ranges, heading = self._ranges, self._heading
        if ranges is None or heading is None:
            if self._last_command not in (None, STOP):
                self._publish(STOP)
            return
        command = self._avoider.step(ranges, heading)
        if command is not None:
            self._publish(command)

    def stop_for_good(self):
        """Publish a zero Twist as the node's last command (the signal's thread and rospy's shutdown hook may
        both call it)."""
        self._cmd_vel.stop_for_good()

    def _publish(self, command):
        if self._cmd_vel.publish(*command):
            self._last_command = command


def cmd_vel_topic(value):
    """The topic name to publish on, from the parameter's `value`; DriveError if it is not a usable name."""
    if not isinstance(value, str) or not value or not rosgraph.names.is_legal_name(value):
        raise DriveError(f"parameter {rospy.resolve_name(CMD_VEL_PARAM)} must be a topic name such as /cmd_vel, "
                         f"got {value!r}")
    return value


def shut_down(node):
    """Ctrl-C or SIGTERM: the robot stops, then rospy shuts down (which ends the loop)."""
    node.stop_for_good()
    rospy.signal_shutdown("stop requested")


def main():
    """Run the node until shutdown; returns the exit code."""
    try:
        rospy.init_node(NODE_NAME, disable_signals=True)   # waits for the master, if need be
    except KeyboardInterrupt:
        return 0   # Ctrl-C while waiting for the master: nothing has started yet
    try:
        topic = cmd_vel_topic(rospy.get_param(CMD_VEL_PARAM, DEFAULT_CMD_VEL_TOPIC))
    except DriveError as error:
        rospy.logfatal("%s: %s", NODE_NAME, error)
        return 1
    rospy.loginfo("TurtleBot3 Simulation Node Init")
    node = DriveNode(topic)
    StopRequest(on_stop=lambda: shut_down(node)).install()
    rate = rospy.Rate(CONTROL_RATE_HZ, reset=True)
    while not rospy.is_shutdown():
        node.tick()
        try:
            rate.sleep()
        except rospy.ROSInterruptException:
            break
    return 0
