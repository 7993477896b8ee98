"""publish_unless_shut_down: a publish that shutdown closed is dropped quietly; before shutdown every error
still reaches the caller."""
import subprocess
import sys
import textwrap

import pytest
import rospy

from stop_request.closed_topic import publish_unless_shut_down, shutting_down


def closed_topic(_message):
    raise rospy.ROSException("publish() to a closed topic")


def test_a_delivered_message_returns_true():
    sent = []
    assert publish_unless_shut_down(sent.append, "hello") is True
    assert sent == ["hello"]


def test_a_closed_topic_before_shutdown_is_still_an_error():
    assert not rospy.is_shutdown() and not shutting_down()
    with pytest.raises(rospy.ROSException, match="closed topic"):
        publish_unless_shut_down(closed_topic, "hello")


def test_a_closed_topic_after_shutdown_returns_false_without_raising():
    # rospy's shutdown cannot be undone in a process, so it happens in a child of its own.
    child = textwrap.dedent("""
        import rospy
        from stop_request.closed_topic import publish_unless_shut_down
        def closed_topic(_message):
            raise rospy.ROSException("publish() to a closed topic")
        rospy.signal_shutdown("Ctrl-C")
        print(publish_unless_shut_down(closed_topic, "hello"))
    """)
    result = subprocess.run([sys.executable, "-c", child], capture_output=True, text=True, timeout=60)
    assert result.returncode == 0, result.stderr
    assert result.stdout.strip() == "False"
    assert "Traceback" not in result.stderr


def test_a_topic_closed_by_rospys_pre_shutdown_cleanup_returns_false_without_raising():
    """rospy closes every topic in a pre-shutdown hook, while rospy.is_shutdown() is still False: a callback
    publishing in that window (seen in a fresh-clone run of the suite) must not print a traceback either."""
    child = textwrap.dedent("""
        import rospy
        from stop_request.closed_topic import publish_unless_shut_down, shutting_down
        def closed_topic(_message):
            raise rospy.ROSException("publish() to a closed topic")
        def during_cleanup(_reason):
            print(rospy.is_shutdown(), shutting_down(), publish_unless_shut_down(closed_topic, "hello"))
        rospy.core.add_preshutdown_hook(during_cleanup)
        rospy.signal_shutdown("Ctrl-C")
    """)
    result = subprocess.run([sys.executable, "-c", child], capture_output=True, text=True, timeout=60)
    assert result.returncode == 0, result.stderr
    assert result.stdout.strip() == "False True False"
    assert "Traceback" not in result.stderr
