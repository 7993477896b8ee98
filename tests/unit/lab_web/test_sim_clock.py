"""The server's sim time without /clock (lab_web.ros_context.RosContext.stamped and now): the newest stamp of the
robot's odometry, kept through a late message, given up for an earlier one after a reset of the simulation."""
import rospy

from lab_web.ros_context import RosContext


def test_sim_time_is_zero_before_any_stamp_as_rospys_before_clock():
    assert RosContext(use_sim_time=True).now() == rospy.Time(0)


def test_sim_time_is_the_newest_stamp_and_a_late_message_does_not_turn_it_back():
    ros = RosContext(use_sim_time=True)
    ros.stamped(rospy.Time(5, 0))
    ros.stamped(rospy.Time(4, 600000000))     # 0.4 s late: another thread's message
    assert ros.now() == rospy.Time(5, 0)
    ros.stamped(rospy.Time(5, 33000000))
    assert ros.now() == rospy.Time(5, 33000000)


def test_a_stamp_over_a_second_back_is_a_reset_of_the_simulation():
    ros = RosContext(use_sim_time=True)
    ros.stamped(rospy.Time(60, 0))
    ros.stamped(rospy.Time(0, 200000000))
    assert ros.now() == rospy.Time(0, 200000000)
