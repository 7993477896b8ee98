"""draw_square's four-state machine (turtlesim tutorials/draw_square.cpp), no ROS.

Every 0.016 s timer tick the driver looks at the latest turtle1 Pose and may publish one
command. The goal is a turtlesim/Pose in the C++, so its fields are float32 and compared with
float32 arithmetic. PI here is the tutorial's own 3.141592. The node calls /reset first; that is
the adapter's job.
"""
import enum
import math

import numpy

from turtlesim.core.geometry import as_float32
from turtlesim.core.log import LogLevel

SQUARE_PI = 3.141592
"""draw_square.cpp's PI macro."""

SIDE_LENGTH_M = 2.0
FORWARD_SPEED = 1.0
"""linear.x in m/s while driving an edge."""

TURN_SPEED = as_float32(0.4)
"""angular.z in rad/s while turning; passes through a float parameter, so 0.4000000059604645."""

POSITION_TOLERANCE_M = 0.1
HEADING_TOLERANCE_RAD = 0.01
STOPPED_TOLERANCE = 0.0001
"""Both pose velocities below this (signed compare, as the original) mean stopped."""

STOP = (0.0, 0.0)


class SquareState(enum.Enum):
    """States of the tutorial, in its order."""

    FORWARD = 0
    STOP_FORWARD = 1
    TURN = 2
    STOP_TURN = 3


class SquareDriver:
    """Drives a 2 m square counter-clockwise from turtle1's first pose, forever."""

    def __init__(self, log):
        """`log`: LogSink for the INFO lines `New goal [x y, theta]` and `Reached goal`."""
        self._log = log
        self._state = SquareState.FORWARD
        self._goal = None

    @property
    def state(self):
        """The current SquareState."""
        return self._state

    def on_timer(self, pose):
        """One timer tick with the latest Pose (None before the first one arrives).

        Returns (linear.x, angular.z) to publish, or None when nothing is published this tick
        (no pose yet, or a stop state just reached its goal and set the next one).
        """
        if pose is None:
            return None
        if self._goal is None:
            self._state = SquareState.FORWARD
            self._set_edge_goal(pose)
        if self._state is SquareState.FORWARD:
            return self._drive(pose, SquareState.STOP_FORWARD, (FORWARD_SPEED, 0.0))
        if self._state is SquareState.TURN:
            return self._drive(pose, SquareState.STOP_TURN, (0.0, TURN_SPEED))
        return self._wait_until_stopped(pose)

    def _drive(self, pose, next_state, command):
        if self._reached_goal(pose):
            self._state = next_state
            return STOP
        return command

    def _wait_until_stopped(self, pose):
        if not (pose.angular_velocity < STOPPED_TOLERANCE
                and pose.linear_velocity < STOPPED_TOLERANCE):
            return STOP
        self._log(LogLevel.INFO, 'Reached goal')
        if self._state is SquareState.STOP_FORWARD:
            self._state = SquareState.TURN
            self._set_turn_goal(pose)
        else:
            self._state = SquareState.FORWARD
            self._set_edge_goal(pose)
        return None

    def _reached_goal(self, pose):
        goal_x, goal_y, goal_theta = self._goal
        return (abs(numpy.float32(pose.x) - goal_x) < POSITION_TOLERANCE_M
                and abs(numpy.float32(pose.y) - goal_y) < POSITION_TOLERANCE_M
                and abs(numpy.float32(pose.theta) - goal_theta) < HEADING_TOLERANCE_RAD)

    def _set_edge_goal(self, pose):
        self._set_goal(math.cos(pose.theta) * SIDE_LENGTH_M + pose.x,
                       math.sin(pose.theta) * SIDE_LENGTH_M + pose.y,
                       pose.theta)

    def _set_turn_goal(self, pose):
        theta = numpy.float32(math.fmod(pose.theta + SQUARE_PI / 2.0, 2 * SQUARE_PI))
        if theta >= SQUARE_PI:
            theta = numpy.float32(float(theta) - 2 * SQUARE_PI)
        self._set_goal(pose.x, pose.y, theta)

    def _set_goal(self, x, y, theta):
        self._goal = (numpy.float32(x), numpy.float32(y), numpy.float32(theta))
        self._log(LogLevel.INFO, 'New goal [%f %f, %f]' % tuple(float(v) for v in self._goal))

