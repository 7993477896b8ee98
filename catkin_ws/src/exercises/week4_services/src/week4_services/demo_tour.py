"""The Week 4 demo tour as data, and its report as a readable table (plain Python, no ROS).

Each stop is one service call a student would make; the runner measures the robot before and after through
/odom and /scan and this module turns the numbers into a row.
"""
import math
from typing import NamedTuple, Tuple


class Stop(NamedTuple):
    """One call of the tour: `service` name, the request fields as positional `args`, and how to read it."""

    service: str
    args: Tuple
    measure: str        # "travel", "turn" or "approach"


TOUR = (
    Stop("/move_service", (True,), "travel"),
    Stop("/move_service", (False,), "travel"),
    Stop("/timed_move_service", ("left", 3), "turn"),
    Stop("/timed_move_service", ("right", 3), "turn"),
    Stop("/timed_move_service", ("back", 2), "travel"),
    Stop("/timed_move_service", ("jump", 2), "travel"),
    Stop("/approach_service", (0.4, 0.1), "approach"),
    Stop("/approach_service", (0.4, 0.5), "approach"),
)


class Pose(NamedTuple):
    x: float
    y: float
    yaw: float


def describe_request(stop):
    return "{} {}".format(stop.service, " ".join(repr(arg) if isinstance(arg, str) else str(arg)
                                                 for arg in stop.args))


def signed_travel(before, after):
    """Metres moved, positive along the starting heading, negative when reversing."""
    dx, dy = after.x - before.x, after.y - before.y
    along = dx * math.cos(before.yaw) + dy * math.sin(before.yaw)
    return math.copysign(math.hypot(dx, dy), along) if abs(along) > 1e-9 else math.hypot(dx, dy)


def turned_deg(before, after):
    return math.degrees(math.atan2(math.sin(after.yaw - before.yaw), math.cos(after.yaw - before.yaw)))


def describe_outcome(stop, before, after, front_distance):
    """The measured outcome of one call, in words and numbers a student can check against the request."""
    if stop.measure == "turn":
        return "turned {:+.1f} deg, moved {:.3f} m".format(turned_deg(before, after),
                                                          math.hypot(after.x - before.x, after.y - before.y))
    if stop.measure == "approach":
        ahead = "nothing ahead" if not math.isfinite(front_distance) else "{:.3f} m".format(front_distance)
        return "front LiDAR {} (asked {:.2f} m), moved {:.3f} m".format(
            ahead, stop.args[0], signed_travel(before, after))
    return "moved {:+.3f} m".format(signed_travel(before, after))


def format_table(header, rows):
    """A plain-text table with a rule under the header; every cell is str()-ed and left-aligned."""
    cells = [list(map(str, header))] + [list(map(str, row)) for row in rows]
    widths = [max(len(row[i]) for row in cells) for i in range(len(header))]
    lines = ["  ".join(cell.ljust(width) for cell, width in zip(row, widths)).rstrip() for row in cells]
    lines.insert(1, "  ".join("-" * width for width in widths))
    return "\n".join(lines)
