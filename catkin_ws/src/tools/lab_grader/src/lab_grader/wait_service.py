"""`python3 -m lab_grader.wait_service NAME SECONDS`: exit 0 once the master (ROS_MASTER_URI) lists service NAME,
1 after SECONDS of wall time without it. The grader runs it inside a submission's network namespace, where it
cannot reach the master itself; unlike rospy.wait_for_service, it needs no node and no /clock."""
import sys
import time

import rosgraph

POLL_S = 0.05


def wait_for_service(name, timeout_s):
    master = rosgraph.Master("/lab_grader_wait")
    deadline = time.monotonic() + timeout_s
    while time.monotonic() < deadline:
        try:
            master.lookupService(name)
            return True
        except (rosgraph.MasterError, OSError):
            time.sleep(POLL_S)
    return False


if __name__ == "__main__":
    sys.exit(0 if wait_for_service(sys.argv[1], float(sys.argv[2])) else 1)
