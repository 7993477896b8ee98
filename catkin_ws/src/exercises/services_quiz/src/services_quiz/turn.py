"""What the /turn server does with a services_quiz_srv/Turn request, as plain data (no ROS)."""
from tb3_client.motion import MAX_ANGULAR_RADPS, InvalidRequest, Motion, check_duration, check_speed

TURN_SIGNS = {"left": 1.0, "right": -1.0}


def turn_motion(direction, angular_velocity, time):
    """Spin on the spot: `direction` right or left, `angular_velocity` in (0, 1.82] rad/s, `time` in 1..60 s."""
    if direction not in TURN_SIGNS:
        raise InvalidRequest("direction '{}' is not one of {}".format(direction, ", ".join(TURN_SIGNS)))
    speed = check_speed("angular_velocity", angular_velocity, MAX_ANGULAR_RADPS)
    return Motion(0.0, TURN_SIGNS[direction] * speed, check_duration("time", time))
