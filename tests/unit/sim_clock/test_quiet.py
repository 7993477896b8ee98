"""sim_clock.quiet: rospy's time condition swapped, before init_node, for one that notifies without Python's
deprecation warning."""
import threading
import warnings

import pytest
import rospy
import rospy.rostime

from sim_clock import quiet_time_notifications


@pytest.fixture
def rospy_time(monkeypatch):
    """rospy's time module with its condition and current time restored after the test."""
    monkeypatch.setattr(rospy.rostime, "_rostime_cond", rospy.rostime._rostime_cond)
    monkeypatch.setattr(rospy.rostime, "_rostime_current", rospy.rostime._rostime_current)
    return rospy.rostime


def test_a_time_update_wakes_a_sleeper_without_a_deprecation_warning(rospy_time):
    with warnings.catch_warnings(record=True) as before:
        warnings.simplefilter("always")
        rospy_time._set_rostime(rospy.Time(1, 0))
    assert [w.category for w in before] == [DeprecationWarning]   # what every /clock message costs otherwise

    quiet_time_notifications()
    condition = rospy_time.get_rostime_cond()
    assert isinstance(condition, threading.Condition)
    woken = threading.Event()

    def sleeper():
        with condition:
            condition.wait(5.0)
        woken.set()

    thread = threading.Thread(target=sleeper, daemon=True)
    with condition:   # the sleeper waits once it gets the lock, after this block
        thread.start()
    with warnings.catch_warnings(record=True) as after:
        warnings.simplefilter("always")
        while not woken.wait(0.01):
            rospy_time._set_rostime(rospy.Time(2, 0))
    assert after == [] and rospy_time._rostime_current == rospy.Time(2, 0)


def test_it_leaves_an_already_replaced_condition_alone(rospy_time):
    quiet_time_notifications()
    replaced = rospy_time.get_rostime_cond()
    quiet_time_notifications()
    assert rospy_time.get_rostime_cond() is replaced
