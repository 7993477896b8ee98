"""What the week6_vision modules share: a course world launched on the module's master with the robot's /odom and
the log (/rosout_agg) subscribed on the module's probe."""
from roslab import wait_for_topic

REAL_TIME_FACTOR = 10


def launch_course_world(ros_master, probe, launch_file, *args):
    """`roslaunch tuos_simulations <launch_file> gui:=false real_time_factor:=10 *args` with TURTLEBOT3_MODEL=waffle;
    returns `probe` once /odom is published."""
    ros_master.env["TURTLEBOT3_MODEL"] = "waffle"
    ros_master.roslaunch("tuos_simulations", launch_file, "gui:=false", f"real_time_factor:={REAL_TIME_FACTOR}",
                         *args)
    wait_for_topic(ros_master.uri, "/odom", timeout_s=60)
    probe.subscribe("/odom", "nav_msgs/Odometry")
    probe.subscribe("/rosout_agg", "rosgraph_msgs/Log")
    return probe
