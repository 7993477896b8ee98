#!/usr/bin/env python3
"""Week 4, part 3: the /timed_move_service server (tuos_msgs/TimedMovement).

movement_request fwd/back drives at ~linear_speed (default 0.1 m/s), left/right turns on the spot at
~angular_speed (default 0.3 rad/s), for `duration` seconds of rospy time; then the robot stops and the reply
is success True. Anything else (an unknown word, duration <= 0 or > 60 s) is refused at once with
success False, the reason in the log, and no motion.
"""
import rospy
from tuos_msgs.srv import TimedMovement, TimedMovementResponse

from tb3_client.robot import Robot, RobotError
from week4_services.requests import (
    DEFAULT_ANGULAR_SPEED_RADPS,
    DEFAULT_LINEAR_SPEED_MPS,
    InvalidRequest,
    timed_movement,
)

NODE_NAME = "timed_move_service_server"
SERVICE_NAME = "timed_move_service"


class TimedMoveServer:
    def __init__(self):
        self.linear_speed = rospy.get_param("~linear_speed", DEFAULT_LINEAR_SPEED_MPS)
        self.angular_speed = rospy.get_param("~angular_speed", DEFAULT_ANGULAR_SPEED_RADPS)
        self.robot = Robot()
        self.service = rospy.Service(SERVICE_NAME, TimedMovement, self.callback)
        rospy.loginfo("The '%s' service is ready to be called...", SERVICE_NAME)

    def callback(self, request):
        try:
            motion = timed_movement(request.movement_request, request.duration,
                                    self.linear_speed, self.angular_speed)
            self.robot.perform(motion, "Moving '{}' for {} seconds...".format(
                request.movement_request.strip(), request.duration))
        except (InvalidRequest, RobotError) as error:
            rospy.logerr("Request refused: %s", error)
            return TimedMovementResponse(False)
        rospy.loginfo("Movement complete.")
        return TimedMovementResponse(True)


def main():
    rospy.init_node(NODE_NAME)
    TimedMoveServer()
    rospy.spin()


if __name__ == "__main__":
    main()
