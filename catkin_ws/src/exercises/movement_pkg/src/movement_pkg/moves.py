"""What the /movement and /move servers do with a request, as plain data (no ROS).

/movement (custom_interfaces/MyCustomServiceMessage): exactly "Turn Right", "Turn Left" or "Stop", the
course's words and speeds; anything else is refused. /move (custom_interfaces/Move): a direction, a speed and
a time in whole seconds; "stop" stops at once and ignores the rest.
"""
from tb3_client.motion import MAX_ANGULAR_RADPS, MAX_LINEAR_MPS, InvalidRequest, Motion, check_duration, check_speed

MOVEMENTS = {
    "Turn Right": (0.1, -0.5),
    "Turn Left": (0.1, 0.5),
    "Stop": (0.0, 0.0),
}

# direction: (linear sign, angular sign)
DIRECTIONS = {
    "forward": (1.0, 0.0),
    "backward": (-1.0, 0.0),
    "left": (0.0, 1.0),
    "right": (0.0, -1.0),
}
STOP = "stop"


def movement_velocity(move):
    """(linear m/s, angular rad/s) for a /movement request, or InvalidRequest."""
    if move not in MOVEMENTS:
        raise InvalidRequest("move '{}' is not one of {}".format(move, ", ".join(MOVEMENTS)))
    return MOVEMENTS[move]


def move_motion(direction, velocity, time):
    """The Motion for a /move request: drive or turn at `velocity` (m/s or rad/s) for `time` seconds."""
    if direction == STOP:
        return Motion(0.0, 0.0, 0.0)
    if direction not in DIRECTIONS:
        raise InvalidRequest("direction '{}' is not one of {}, {}".format(direction, ", ".join(DIRECTIONS), STOP))
    linear_sign, angular_sign = DIRECTIONS[direction]
    limit = MAX_LINEAR_MPS if linear_sign else MAX_ANGULAR_RADPS
    speed = check_speed("velocity", velocity, limit)
    return Motion(linear_sign * speed, angular_sign * speed, check_duration("time", time))
