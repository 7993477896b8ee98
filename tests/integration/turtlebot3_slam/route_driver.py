#!/usr/bin/env python3
"""The SLAM tests' scripted drive: a rospy node that steers the robot along a route on /cmd_vel.

    route_driver.py WORLD_NAME OUT_JSON

It follows roslab.mapping_routes.ROUTES[WORLD_NAME] at CONTROL_HZ of sim time, steering by the simulator's ground
truth (/gazebo/model_states: the robot's model, named as the world's launch file names it), which only the test
sees - the SLAM under test gets /scan and odometry only. At the end the robot stops and OUT_JSON gets the laser
positions along the route (every RECORD_STEP_M), for the map's recall. Prints `done` when finished.
"""
import json
import math
import os
import sys
from pathlib import Path

import rospy
from gazebo_msgs.msg import ModelStates
from geometry_msgs.msg import Twist

sys.path.insert(0, str(Path(__file__).resolve().parents[2]))
from roslab.mapping_routes import ROUTES, steer  # noqa: E402  (needs the sys.path entry above)

CONTROL_HZ = 20.0
RECORD_STEP_M = 0.25
LASER_BEHIND_M = 0.064


class RouteDriver:
    def __init__(self, robot, waypoints):
        self.robot = robot
        self.waypoints = waypoints
        self.pose = None
        self.laser_positions = []
        self.commands = rospy.Publisher("/cmd_vel", Twist, queue_size=1)
        rospy.Subscriber("/gazebo/model_states", ModelStates, self._on_states, queue_size=1)

    def _on_states(self, message):
        if self.robot in message.name:
            pose = message.pose[message.name.index(self.robot)]
            q = pose.orientation
            yaw = math.atan2(2.0 * (q.w * q.z + q.x * q.y), 1.0 - 2.0 * (q.y * q.y + q.z * q.z))
            self.pose = (pose.position.x, pose.position.y, yaw)

    def run(self):
        rate = rospy.Rate(CONTROL_HZ)
        while self.pose is None and not rospy.is_shutdown():
            rate.sleep()
        for waypoint in self.waypoints:
            while not rospy.is_shutdown():
                self._record()
                command = steer(self.pose, waypoint)
                if command is None:
                    break
                self._command(*command)
                rate.sleep()
        self._command(0.0, 0.0)

    def _command(self, linear, angular):
        twist = Twist()
        twist.linear.x, twist.angular.z = linear, angular
        self.commands.publish(twist)

    def _record(self):
        x, y, yaw = self.pose
        laser = (x - LASER_BEHIND_M * math.cos(yaw), y - LASER_BEHIND_M * math.sin(yaw))
        if not self.laser_positions or math.dist(laser, self.laser_positions[-1]) >= RECORD_STEP_M:
            self.laser_positions.append(laser)


def main():
    world, out_path = sys.argv[1:]
    rospy.init_node("route_driver")
    route = ROUTES[world]
    driver = RouteDriver(route.robot_name(os.environ["TURTLEBOT3_MODEL"]), route.waypoints)
    driver.run()
    with open(out_path, "w") as out:
        json.dump(driver.laser_positions, out)
    print("done", flush=True)


if __name__ == "__main__":
    main()
