"""The gazebo_server service's answer: the /scan range at index `direction`.

The TurtleBot3 LiDAR publishes 360 ranges, one per degree counter-clockwise from straight ahead, so the
index is the bearing in degrees (0 ahead, 90 left, 180 behind, 270 right). A scan with another number of
ranges allows the indices it has; an inf range means nothing was seen within range_max.
"""
from .errors import ScanLookupError, UsageError

SCAN_TOPIC = "/scan"
NOMINAL_DIRECTIONS = range(0, 360)


def range_at(ranges, direction):
    """ranges[direction] in metres; `ranges` is None until the first scan has arrived.

    Raises ScanLookupError naming the allowed indices instead of an IndexError (and instead of Python's
    negative indexing, which would silently answer -1 with the last range).
    """
    if ranges is None:
        raise ScanLookupError("no {} message received yet: is the robot (or the simulator) running?".format(
            SCAN_TOPIC))
    if not ranges:
        raise ScanLookupError("the latest {} message has no ranges".format(SCAN_TOPIC))
    if not 0 <= direction < len(ranges):
        raise ScanLookupError("direction must be an index from 0 to {} (the latest {} has {} ranges, one per "
                              "degree counter-clockwise from ahead); got {}".format(
                                  len(ranges) - 1, SCAN_TOPIC, len(ranges), direction))
    return ranges[direction]


def usage(program):
    return ("usage: {} [DIRECTION]\n"
            "  prints the LiDAR distance at DIRECTION degrees (0 ahead, 90 left; default 0), 5 times a second;\n"
            "  DIRECTION is an integer from {} to {}").format(
                program, NOMINAL_DIRECTIONS[0], NOMINAL_DIRECTIONS[-1])


def parse_direction(args):
    """The scan client's optional DIRECTION argument (default 0), an integer bearing in 0..359 degrees."""
    if len(args) > 1:
        raise UsageError("expected at most 1 argument, DIRECTION; got {}".format(len(args)))
    if not args:
        return 0
    try:
        direction = int(args[0])
    except ValueError:
        raise UsageError("{!r} is not an integer".format(args[0])) from None
    if direction not in NOMINAL_DIRECTIONS:
        raise UsageError("direction {} is outside {}..{}".format(
            direction, NOMINAL_DIRECTIONS[0], NOMINAL_DIRECTIONS[-1]))
    return direction
