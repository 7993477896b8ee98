"""The /detect_fruit_service answer: for "apple" or "banana", what the LiDAR sees ahead, in words.

The simulated robot has no camera yet, so a fruit is "something ahead within LiDAR range" (a camera-based
version comes when the simulator has one). Any other word succeeds with an "unknown" message, as the course's
node does.
"""
from typing import NamedTuple, Optional

from tb3_client.scan_ahead import ObjectAhead

FRUITS = ("apple", "banana")


class FruitReport(NamedTuple):
    success: bool
    message: str


def fruit_report(detect: str, ahead: Optional[ObjectAhead], have_scan: bool) -> FruitReport:
    """The service reply for request `detect`, given the closest object ahead (None: nothing in range)."""
    fruit = detect.strip().lower()
    if fruit not in FRUITS:
        return FruitReport(True, "unknown fruit '{}': I can look for an {} or a {}".format(detect, *FRUITS))
    if not have_scan:
        return FruitReport(False, "looking for the {}: no /scan received yet, is the robot running?".format(fruit))
    if ahead is None:
        return FruitReport(True, "looking for the {}: nothing within LiDAR range ahead".format(fruit))
    side = "left" if ahead.angle_deg > 0 else "right"
    return FruitReport(True, "looking for the {}: something {:.2f} m ahead, {:.0f} degrees to the {}".format(
        fruit, ahead.distance, abs(ahead.angle_deg), side))
