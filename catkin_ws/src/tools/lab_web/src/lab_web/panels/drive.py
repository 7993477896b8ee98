"""The drive panel: teleop from the page's arrow keys and buttons to <ns>/cmd_vel (the robot) or
/turtle1/cmd_vel, made safe by lab_web.teleop.TeleopGate (a fixed 10 Hz while commands come, zero once after)."""
import threading

import rospy
from geometry_msgs.msg import Twist

from lab_web import commands
from lab_web.panels.base import Panel
from lab_web.ros_context import now_s
from lab_web.teleop import PUBLISH_RATE_HZ, TELEOP_LIMITS, TeleopGate


class DrivePanel(Panel):
    name = "drive"
    COMMANDS = {
        "teleop": commands.CommandSpec(
            (("target", commands.one_of(tuple(TELEOP_LIMITS))),
             ("linear", commands.limited_by(TELEOP_LIMITS, "target", 0)),
             ("angular", commands.limited_by(TELEOP_LIMITS, "target", 1))),
            "linear m/s, angular rad/s (refused beyond the target's limits, never clamped), repeated at ~10 Hz "
            "while a key or button is held and zeros once on release. The server publishes at a fixed 10 Hz while "
            "commands keep coming and zero once they stop (0.3 s) or the page goes away"),
    }

    def __init__(self, ros):
        super().__init__(ros)
        self.gate = TeleopGate()
        self._stop = threading.Event()
        self._thread = threading.Thread(target=self._loop, daemon=True, name="lab_web_teleop")
        self._thread.start()
        ros.follow_robot(self._on_robot_picked)

    def hello(self):
        return {"teleop_limits": {target: list(limits) for target, limits in TELEOP_LIMITS.items()}}

    def handle(self, session, kind, args):
        self.gate.command(session.owner, args["target"], args["linear"], args["angular"], now_s())
        if args["linear"] == 0.0 and args["angular"] == 0.0:
            self._publish()   # a released key stops the robot now, not at the next tick

    def _loop(self):
        while not self._stop.wait(1.0 / PUBLISH_RATE_HZ):
            self._publish()

    def _publish(self, robot_topic=None):
        """Publish what the gate says now; the robot's commands go to `robot_topic` (default: the robot's)."""
        for target, linear, angular in self.gate.tick(now_s()):
            robot_topic = robot_topic or self.ros.name("cmd_vel")
            publisher = self.ros.publisher(robot_topic if target == "robot" else "/turtle1/cmd_vel", Twist)
            twist = Twist()
            twist.linear.x, twist.angular.z = linear, angular
            try:
                publisher.publish(twist)
            except rospy.ROSException:
                return   # shutting down

    def _on_robot_picked(self, old_namespace):
        """Another robot: the one being driven stops first (every target gets zero once, as on shutdown)."""
        self.gate.stop_all(now_s())
        self._publish("{}/cmd_vel".format(old_namespace))

    def disconnect(self, owner):
        self.gate.disconnect(owner, now_s())
        self._publish()

    def shutdown(self):
        """Zero every target a page was driving, then stop the thread."""
        self.gate.stop_all(now_s())
        self._publish()
        self._stop.set()
