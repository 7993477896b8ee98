"""explore_lite's ~frontiers markers: ids, types, colours, sphere sizes and DELETEs for markers no longer used."""
import rospy
from visualization_msgs.msg import Marker

from explore_lite.markers import frontier_markers
from lab_nav.exploration.frontier_search import Frontier

CHEAP = Frontier(initial=(1.0, 2.0), size=3, centroid=(0.7, 1.3), cost=-1.0, points=[(1.0, 2.05), (1.0, 2.1)])
DEAR = Frontier(initial=(3.0, 0.0), size=2, centroid=(2.0, 0.0), cost=2.0, points=[(3.05, 0.0)])


def test_each_frontier_gets_its_points_and_a_sphere_at_its_seed():
    array, count = frontier_markers([CHEAP, DEAR], lambda point: point == (2.0, 0.0), "map", rospy.Time(5), 0)
    markers = array.markers
    assert count == 4
    assert [(m.id, m.type, m.action, m.ns) for m in markers] == [
        (0, Marker.POINTS, Marker.ADD, "frontiers"), (1, Marker.SPHERE, Marker.ADD, "frontiers"),
        (2, Marker.POINTS, Marker.ADD, "frontiers"), (3, Marker.SPHERE, Marker.ADD, "frontiers")]
    assert [(p.x, p.y) for p in markers[0].points] == [(1.0, 2.05), (1.0, 2.1)]
    # blue, and red when blacklisted
    assert (markers[0].color.r, markers[0].color.b, markers[2].color.r, markers[2].color.b) == (0, 1, 1, 0)
    assert (markers[1].pose.position.x, markers[1].pose.position.y, markers[1].color.g) == (1.0, 2.0, 1.0)
    assert markers[0].scale.x == 0.1
    assert markers[1].scale.x == 0.4                                        # min(|0.4 * -1 / -1|, 0.5)
    assert markers[3].scale.x == 0.2                                        # |0.4 * -1 / 2|: dearer, smaller
    assert all(m.header.frame_id == "map" and m.header.stamp == rospy.Time(5) and m.frame_locked for m in markers)


def test_markers_no_longer_used_are_deleted():
    array, count = frontier_markers([DEAR], lambda point: False, "map", rospy.Time(6), 4)
    assert count == 2
    assert [(m.id, m.action) for m in array.markers] == [(0, Marker.ADD), (1, Marker.ADD), (2, Marker.DELETE),
                                                         (3, Marker.DELETE)]
    assert frontier_markers([], lambda point: False, "map", rospy.Time(7), 2)[0].markers[1].id == 1
