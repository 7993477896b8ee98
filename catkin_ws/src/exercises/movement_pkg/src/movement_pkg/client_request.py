"""What movement_client asks for, from its command-line arguments (no ROS).

One argument is a /movement request (custom_interfaces/MyCustomServiceMessage): `movement_client "Turn Right"`.
Three are a /move request (custom_interfaces/Move): direction, velocity (m/s, or rad/s for left and right) and
time (whole seconds): `movement_client left 0.2 5`. The servers check the values themselves.
"""
from collections import namedtuple

from movement_pkg.moves import DIRECTIONS, MOVEMENTS, STOP, InvalidRequest

USAGE = ('usage: rosrun movement_pkg movement_client "<move>"                   (one of: {})\n'
         '       rosrun movement_pkg movement_client <direction> <velocity> <time>  (direction: {}, {})'
         .format(", ".join(MOVEMENTS), ", ".join(DIRECTIONS), STOP))

ClientRequest = namedtuple("ClientRequest", "service fields")
"""The service to call (/movement or /move) and the request's field values, in order."""


def client_request(arguments):
    """The ClientRequest for movement_client's `arguments` (after rospy.myargv); InvalidRequest naming what is
    wrong when they are neither one move nor a direction, a number and a whole number."""
    if len(arguments) == 1:
        return ClientRequest("/movement", (arguments[0],))
    if len(arguments) == 3:
        direction, velocity, time = arguments
        try:
            velocity = float(velocity)
        except ValueError:
            raise InvalidRequest("velocity '{}' is not a number".format(velocity)) from None
        try:
            time = int(time)
        except ValueError:
            raise InvalidRequest("time '{}' is not a whole number of seconds".format(time)) from None
        return ClientRequest("/move", (direction, velocity, time))
    raise InvalidRequest("expected one move or a direction, a velocity and a time; got {} arguments"
                         .format(len(arguments)))
