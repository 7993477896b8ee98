"""`rosrun tb3_sim spawn_box NAME X Y [--size SX [SY]] [--height H] [--yaw YAW] [--static] [--mass KG]
[--color C]`: place a box the way Gazebo's box tool does, through /gazebo/spawn_sdf_model.

Units: metres, radians, kilograms; X, Y, YAW in the world frame (or in --reference-frame, a model name).
Defaults: a 0.3 m cube of 1 kg, dynamic (the robot can push it), yaw 0, Gazebo's default grey; --color takes
what a world file's `color` takes (red, "#ff8800", Gazebo/Red) and shows in the camera. The box is visible to
the LiDAR only if it is at least 0.132 m tall (the scan plane), as in Gazebo. Prints the service's
status_message; exits 0 on success, 1 on failure (service refused, or no simulator within --timeout seconds), 2 on
bad arguments.
"""

import argparse
import math
import sys

import rospy
from gazebo_msgs.srv import SpawnModel, SpawnModelRequest

from tb3_sim.core.geometry import Pose2D
from tb3_sim.core.materials import colour_from_name_or_hex
from tb3_sim.core.model_xml import box_sdf
from tb3_sim.ros import messages

SPAWN_SERVICE = "/gazebo/spawn_sdf_model"
DEFAULT_SIZE_M = 0.3
DEFAULT_MASS_KG = 1.0
DEFAULT_TIMEOUT_S = 10.0


def _finite(text):
    try:
        value = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"not a number: {text!r}") from None
    if not math.isfinite(value):
        raise argparse.ArgumentTypeError(f"not a finite number: {text!r}")
    return value


def _positive(text):
    value = _finite(text)
    if value <= 0:
        raise argparse.ArgumentTypeError(f"must be > 0: {text!r}")
    return value


def _colour(text):
    try:
        return colour_from_name_or_hex(text)
    except ValueError as error:
        raise argparse.ArgumentTypeError(str(error)) from None


def parser():
    result = argparse.ArgumentParser(prog="spawn_box", description=__doc__.split("\n\n")[0],
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    result.add_argument("name", help="model name (must not exist yet)")
    result.add_argument("x", type=_finite, help="x of the box centre (m)")
    result.add_argument("y", type=_finite, help="y of the box centre (m)")
    result.add_argument("--size", type=_positive, nargs="+", metavar="S", default=[DEFAULT_SIZE_M],
                        help="footprint: one value for a square, or SX SY (m; default 0.3)")
    result.add_argument("--height", type=_positive, help="height (m; default: the first --size value)")
    result.add_argument("--yaw", type=_finite, default=0.0, help="heading (rad, CCW from +x; default 0)")
    result.add_argument("--static", action="store_true", help="a static box the robot cannot push")
    result.add_argument("--mass", type=_positive, default=DEFAULT_MASS_KG, help="mass (kg; default 1)")
    result.add_argument("--color", type=_colour, help="colour the camera sees: a name, #rrggbb or Gazebo/Red")
    result.add_argument("--reference-frame", default="", help="a model whose frame X, Y, YAW are given in")
    result.add_argument("--timeout", type=_positive, default=DEFAULT_TIMEOUT_S,
                        help="seconds to wait for the simulator (default 10)")
    return result


def parse_args(argv):
    """Parsed and checked arguments; exits 2 with a usage message on bad ones (argparse's convention)."""
    arg_parser = parser()
    args = arg_parser.parse_args(argv)
    if len(args.size) > 2:
        arg_parser.error(f"--size takes one or two values, got {len(args.size)}")
    return args


def spawn_request(args):
    """The SpawnModel request for parsed `args`."""
    size_x, size_y = args.size[0], args.size[-1]
    height = args.height if args.height is not None else size_x
    return SpawnModelRequest(model_name=args.name,
                             model_xml=box_sdf(args.name, size_x, size_y, height, args.static, args.mass,
                                               args.color),
                             initial_pose=messages.pose_message(Pose2D(args.x, args.y, args.yaw)),
                             reference_frame=args.reference_frame)


def describe(args):
    """One line about the box `args` describe, e.g. "0.3 x 0.3 x 0.3 m, 1 kg, at (1.2, 0) yaw 0"."""
    height = args.height if args.height is not None else args.size[0]
    where = f" in '{args.reference_frame}'" if args.reference_frame else ""
    kind = "static" if args.static else f"{args.mass:g} kg"
    return (f"{args.size[0]:g} x {args.size[-1]:g} x {height:g} m, {kind}, at ({args.x:g}, {args.y:g}) "
            f"yaw {args.yaw:g}{where}")


def main(argv=None):
    args = parse_args(rospy.myargv(sys.argv if argv is None else argv)[1:])
    try:
        rospy.wait_for_service(SPAWN_SERVICE, timeout=args.timeout)
        reply = rospy.ServiceProxy(SPAWN_SERVICE, SpawnModel)(spawn_request(args))
    except rospy.ROSException:
        print(f"spawn_box: {SPAWN_SERVICE} is not available after {args.timeout:g} s; is the simulator running?",
              file=sys.stderr)
        return 1
    except rospy.ServiceException as error:
        print(f"spawn_box: the call to {SPAWN_SERVICE} failed: {error}", file=sys.stderr)
        return 1
    except KeyboardInterrupt:
        return 1
    if not reply.success:
        print(f"spawn_box: {reply.status_message}", file=sys.stderr)
        return 1
    print(f"{reply.status_message}: '{args.name}', {describe(args)}")
    return 0
