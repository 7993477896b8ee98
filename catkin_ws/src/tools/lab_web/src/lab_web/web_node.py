"""The lab_web node: reads its ~params, starts the ROS bridge and serves the page until Ctrl-C. When roscore is
restarted, it registers its topics and services with the new master (master_reconnect), as the lab's other nodes
do, so the page's pose, teleop and graph come back by themselves.

~host (str, 127.0.0.1): the address to listen on; anything but loopback needs a token (see lab_web.access).
~port (int, 8080): the port; taken ports are reported with the launch argument that changes it.
~token (str, ""): the page's token when ~host is not loopback (empty: a random one, printed with the URL).
~robot_namespace (str, ""): the robot whose odom, scan, camera and cmd_vel the page shows and drives.
~service_timeout (float, 120): seconds a service form call may take; one that has not answered by then is
    abandoned and the page says which service did not answer.
"""
import math
import sys
from pathlib import Path

import rospkg
import rospy
from aiohttp import web

from lab_web.access import AccessError, AccessPolicy
from lab_web.ros_bridge import RosBridge
from lab_web.ros_context import DEFAULT_SERVICE_TIMEOUT_S
from lab_web.server import make_app
from master_reconnect import keep_registered


def static_dir():
    return Path(rospkg.RosPack().get_path("lab_web")) / "static"


def main():
    # aiohttp handles Ctrl-C and stops the bridge itself; the node's sim time comes from the stamps it receives,
    # not /clock (lab_web.ros_context.RosContext.now).
    rospy.init_node("lab_web", disable_signals=True, disable_rostime=True)
    port = rospy.get_param("~port", 8080)
    try:
        if isinstance(port, bool) or not isinstance(port, int) or not 1 <= port <= 65535:
            raise AccessError("port must be a number from 1 to 65535, got {!r}".format(port))
        policy = AccessPolicy(str(rospy.get_param("~host", "127.0.0.1")), str(rospy.get_param("~token", "")))
        service_timeout = rospy.get_param("~service_timeout", DEFAULT_SERVICE_TIMEOUT_S)
        if isinstance(service_timeout, bool) or not isinstance(service_timeout, (int, float)) \
                or not 0 < service_timeout < math.inf:
            raise AccessError("service_timeout must be a number of seconds > 0, got {!r}".format(service_timeout))
    except AccessError as error:
        rospy.logfatal("lab_web: %s", error)
        sys.exit(2)
    bridge = RosBridge(str(rospy.get_param("~robot_namespace", "")), service_timeout,
                       use_sim_time=bool(rospy.get_param("/use_sim_time", False)))
    keep_registered()
    if policy.warning():
        rospy.logwarn(policy.warning())
    try:
        # aiohttp's start-up line, printed once the port is bound: the address appears when the page is up.
        web.run_app(make_app(bridge, policy, static_dir()), host=policy.host, port=port,
                    print=lambda _started: rospy.loginfo("lab_web: open %s in a browser", policy.url(port)),
                    access_log=None, handle_signals=True)
    except OSError as error:
        rospy.logfatal("lab_web: cannot listen on %s:%s (%s): another program uses the port? Choose another with "
                       "port:=<number>", policy.host, port, error.strerror or error)
        sys.exit(1)
    finally:
        bridge.shutdown()
        rospy.signal_shutdown("lab_web stopped")
