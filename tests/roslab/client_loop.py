"""A course-style client node for timing tests: a `rospy.Rate(hz)` loop (or `rospy.sleep(1 / hz)` with `--sleep`)
running for `duration` seconds of ROS time, printing as JSON the ROS time it started at and the ROS time of every
wake-up. Run with the lab's python against a master whose /use_sim_time is set:

    python client_loop.py 10 5 [--sleep]
"""
import json
import sys

import rospy
from rosgraph_msgs.msg import Clock


def main(argv):
    hz, duration_s = float(argv[1]), float(argv[2])
    use_sleep = "--sleep" in argv
    rospy.init_node("client_loop", anonymous=True)
    rospy.wait_for_message("/clock", Clock, timeout=30)
    rate = rospy.Rate(hz)
    start_s = rospy.get_time()
    wakes = []
    while not rospy.is_shutdown() and rospy.get_time() < start_s + duration_s:
        if use_sleep:
            rospy.sleep(1.0 / hz)
        else:
            rate.sleep()
        wakes.append(rospy.get_time())
    print(json.dumps({"start": start_s, "wakes": wakes}))


if __name__ == "__main__":
    main(rospy.myargv(sys.argv))
