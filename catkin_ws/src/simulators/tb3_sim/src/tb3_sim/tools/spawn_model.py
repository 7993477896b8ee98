"""`rosrun tb3_sim spawn_model -sdf -file box.sdf -model box1 -x 1 -y 0 -Y 0.5`: gazebo_ros's spawn_model
command line over /gazebo/spawn_sdf_model and spawn_urdf_model (tb3_sim or Gazebo).

Options as gazebo_ros (noetic): -urdf | -sdf; -file FILE | -param PARAM | -stdin; -model NAME (required);
-x -y -z -R -P -Y (m, rad; z, roll and pitch are sent, and tb3_sim ignores them); -reference_frame FRAME;
-gazebo_namespace NS (default /gazebo); -robot_namespace NS (default: the namespace spawn_model runs in, as
gazebo_ros's: a TurtleBot3 spawned in <group ns="tb3_0"> gets /tb3_0/cmd_vel, /tb3_0/odom, ...); -unpause;
-wait MODEL (wait until that model exists first); -timeout S (seconds to wait for the service, default 10).
Accepted and ignored, as they have no meaning here: -J JOINT POSITION (repeatable), -package_to_model, -b.
-database is refused (no model database).
Prints Gazebo's "Spawn status: ..." line; exits 1 with "Spawn service failed. Exiting." when the spawn fails.
"""

import argparse
import sys
import time

import rospy
from gazebo_msgs.srv import GetWorldProperties, SpawnModel, SpawnModelRequest
from geometry_msgs.msg import Pose
from std_srvs.srv import Empty

from tb3_sim.ros.messages import rpy_to_quaternion

DEFAULT_TIMEOUT_S = 10.0
WAIT_POLL_S = 0.2


def parser():
    result = argparse.ArgumentParser(prog="spawn_model", description=__doc__.split("\n\n")[0])
    kind = result.add_mutually_exclusive_group(required=True)
    kind.add_argument("-urdf", action="store_true", help="the model is URDF")
    kind.add_argument("-sdf", action="store_true", help="the model is SDF")
    source = result.add_mutually_exclusive_group(required=True)
    source.add_argument("-file", help="read the model from this file")
    source.add_argument("-param", help="read the model from this ROS parameter")
    source.add_argument("-stdin", action="store_true", help="read the model from standard input")
    source.add_argument("-database", help="not supported: tb3_sim has no model database")
    result.add_argument("-model", required=True, help="name of the new model")
    for axis in ("x", "y", "z", "R", "P", "Y"):
        result.add_argument("-" + axis, type=float, default=0.0, help=f"initial pose: {axis}")
    result.add_argument("-reference_frame", default="", help="frame of the initial pose (a model, or world)")
    result.add_argument("-gazebo_namespace", default="/gazebo", help="namespace of the services")
    result.add_argument("-robot_namespace", default=rospy.get_namespace(),
                        help="namespace of the robot's topics (default: the namespace spawn_model runs in)")
    result.add_argument("-unpause", action="store_true", help="unpause physics after spawning")
    result.add_argument("-wait", metavar="MODEL", help="wait until MODEL exists before spawning")
    result.add_argument("-timeout", type=float, default=DEFAULT_TIMEOUT_S, help="seconds to wait for the service")
    result.add_argument("-J", nargs=2, action="append", metavar=("JOINT", "POSITION"), help="ignored")
    result.add_argument("-package_to_model", action="store_true", help="ignored")
    result.add_argument("-b", action="store_true", help="ignored (bond)")
    return result


def read_model(args):
    """The model text from -file, -param or -stdin; raises ValueError with the reason."""
    if args.database:
        raise ValueError("-database is not supported by tb3_sim (no model database); use -file or -param")
    if args.file:
        print(f"Loading model XML from file {args.file}")
        try:
            with open(args.file, encoding="utf-8") as model_file:
                return model_file.read()
        except OSError as error:
            raise ValueError(f"cannot read {args.file}: {error.strerror}") from None
    if args.param:
        print(f"Loading model XML from ros parameter {args.param}")
        if not rospy.has_param(args.param):
            raise ValueError(f"parameter {args.param} does not exist")
        return rospy.get_param(args.param)
    print("Loading model XML from stdin")
    return sys.stdin.read()


def spawn_request(args, model_xml):
    pose = Pose()
    pose.position.x, pose.position.y, pose.position.z = args.x, args.y, args.z
    (pose.orientation.x, pose.orientation.y, pose.orientation.z,
     pose.orientation.w) = rpy_to_quaternion(args.R, args.P, args.Y)
    return SpawnModelRequest(model_name=args.model, model_xml=model_xml, robot_namespace=args.robot_namespace,
                             initial_pose=pose, reference_frame=args.reference_frame)


def _service(namespace, name):
    return namespace.rstrip("/") + "/" + name


def _wait_for_model(namespace, model, timeout_s):
    properties = rospy.ServiceProxy(_service(namespace, "get_world_properties"), GetWorldProperties)
    deadline = time.monotonic() + timeout_s
    while model not in properties().model_names:
        if time.monotonic() > deadline:
            raise rospy.ROSException(f"model {model} did not appear within {timeout_s:g} s")
        time.sleep(WAIT_POLL_S)


def main(argv=None):
    args = parser().parse_args(rospy.myargv(sys.argv if argv is None else argv)[1:])
    service = _service(args.gazebo_namespace, "spawn_urdf_model" if args.urdf else "spawn_sdf_model")
    try:
        model_xml = read_model(args)
        print(f"Waiting for service {service}")
        rospy.wait_for_service(service, timeout=args.timeout)
        if args.wait:
            _wait_for_model(args.gazebo_namespace, args.wait, args.timeout)
        print(f"Calling service {service}")
        reply = rospy.ServiceProxy(service, SpawnModel)(spawn_request(args, model_xml))
        print(f"Spawn status: {reply.status_message}")
        if not reply.success:
            print("Spawn service failed. Exiting.", file=sys.stderr)
            return 1
        if args.unpause:
            rospy.ServiceProxy(_service(args.gazebo_namespace, "unpause_physics"), Empty)()
    except ValueError as error:
        print(f"spawn_model: {error}", file=sys.stderr)
        return 1
    except (rospy.ROSException, rospy.ServiceException) as error:
        print(f"spawn_model: {error}", file=sys.stderr)
        return 1
    except KeyboardInterrupt:
        return 1
    return 0
