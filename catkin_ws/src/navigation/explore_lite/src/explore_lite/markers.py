"""explore_lite's ~frontiers MarkerArray: per frontier a POINTS marker of its cells (ns "frontiers", 0.1 m, blue,
red when its centroid is blacklisted) and a green SPHERE at its seed cell sized min(|0.4 * cheapest cost / cost|,
0.5) m, ids counting up in that order; markers left over from a longer previous array are sent as DELETE.
Every marker lives forever and is frame-locked, as in the original."""

from geometry_msgs.msg import Point
from std_msgs.msg import ColorRGBA
from visualization_msgs.msg import Marker, MarkerArray

NAMESPACE = "frontiers"
POINT_SCALE_M = 0.1
MAX_SPHERE_M = 0.5
SPHERE_COST_FACTOR = 0.4
BLUE, RED, GREEN = ColorRGBA(0, 0, 1, 1), ColorRGBA(1, 0, 0, 1), ColorRGBA(0, 1, 0, 1)


def _marker(frame_id, stamp, marker_id, marker_type, scale, color):
    marker = Marker(ns=NAMESPACE, id=marker_id, type=marker_type, action=Marker.ADD, color=color,
                    frame_locked=True)
    marker.header.frame_id, marker.header.stamp = frame_id, stamp
    marker.scale.x = marker.scale.y = marker.scale.z = scale
    return marker


def _sphere_scale(min_cost, cost):
    if cost == 0:
        return MAX_SPHERE_M
    return min(abs(min_cost * SPHERE_COST_FACTOR / cost), MAX_SPHERE_M)


def frontier_markers(frontiers, blacklisted, frame_id, stamp, previous_count):
    """(MarkerArray, the count of ADD markers in it) for `frontiers` sorted by cost; `blacklisted(point)` says
    whether a centroid is on the blacklist; `previous_count` is the count returned last time."""
    markers = []
    min_cost = frontiers[0].cost if frontiers else 0.0
    for frontier in frontiers:
        points = _marker(frame_id, stamp, len(markers), Marker.POINTS, POINT_SCALE_M,
                         RED if blacklisted(frontier.centroid) else BLUE)
        points.points = [Point(x, y, 0.0) for x, y in frontier.points]
        markers.append(points)
        sphere = _marker(frame_id, stamp, len(markers), Marker.SPHERE, _sphere_scale(min_cost, frontier.cost), GREEN)
        sphere.pose.position = Point(frontier.initial[0], frontier.initial[1], 0.0)
        markers.append(sphere)
    count = len(markers)
    for marker_id in range(count, previous_count):
        stale = _marker(frame_id, stamp, marker_id, Marker.SPHERE, MAX_SPHERE_M, GREEN)
        stale.action = Marker.DELETE
        markers.append(stale)
    return MarkerArray(markers=markers), count
