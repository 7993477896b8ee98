#!/usr/bin/env python3
"""quaternion_demo.py [ROLL PITCH YAW]: converts roll/pitch/yaw (radians) to a quaternion with
tf.transformations and back, and checks that the round trip gives the same rotation.

A plain script: it needs no roscore. Wrong arguments print the usage and exit with 1.
"""
import sys

from beginner_tutorials.errors import UsageError
from beginner_tutorials.quaternions import parse_angles, same_rotation, to_euler, to_quaternion, usage


def format_values(values):
    return " ".join("{:.4f}".format(value) for value in values)


def main():
    try:
        angles = parse_angles(sys.argv[1:])
    except UsageError as error:
        print("error: {}\n{}".format(error, usage("quaternion_demo.py")), file=sys.stderr)
        return 1
    quaternion = to_quaternion(angles)
    angles_back = to_euler(quaternion)
    print("roll pitch yaw (rad):      {}".format(format_values(angles)))
    print("quaternion x y z w:        {}".format(format_values(quaternion)))
    print("back to roll pitch yaw:    {}".format(format_values(angles_back)))
    print("same rotation: {}".format("yes" if same_rotation(quaternion, to_quaternion(angles_back)) else "no"))
    return 0


if __name__ == "__main__":
    sys.exit(main())
