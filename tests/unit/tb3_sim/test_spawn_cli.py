"""spawn_box's arguments -> the SpawnModel request (no master needed)."""
import math

import pytest

from tb3_sim.core.model_xml import parse_model_xml
from tb3_sim.core.shapes import Box
from tb3_sim.tools.spawn_box import describe, parse_args, spawn_request


def test_defaults_make_a_dynamic_cube():
    args = parse_args(["box1", "1.2", "0"])
    request = spawn_request(args)
    spec = parse_model_xml(request.model_xml)
    assert (request.model_name, spec.shape, spec.static, spec.mass_kg) == ("box1", Box(0.3, 0.3, 0.3), False, 1.0)
    assert spec.rgb is None
    assert (request.initial_pose.position.x, request.initial_pose.position.y) == (1.2, 0.0)
    assert request.reference_frame == ""


def test_every_option():
    args = parse_args(["crate", "-1", "2.5", "--size", "0.2", "0.4", "--height", "0.1", "--yaw", "1.5707963",
                       "--static", "--mass", "3", "--reference-frame", "box1", "--color", "Gazebo/Red"])
    request = spawn_request(args)
    spec = parse_model_xml(request.model_xml)
    assert spec.shape == Box(0.2, 0.4, 0.1) and spec.static and spec.rgb == (255, 0, 0)
    assert 2 * math.atan2(request.initial_pose.orientation.z, request.initial_pose.orientation.w) == \
        pytest.approx(1.5707963)
    assert request.reference_frame == "box1"
    assert describe(args) == "0.2 x 0.4 x 0.1 m, static, at (-1, 2.5) yaw 1.5708 in 'box1'"


@pytest.mark.parametrize("argv, message", [
    (["b", "x", "0"], "not a number: 'x'"),
    (["b", "0", "nan"], "not a finite number: 'nan'"),
    (["b", "0", "0", "--size", "-1"], "must be > 0: '-1'"),
    (["b", "0", "0", "--size", "1", "2", "3"], "--size takes one or two values, got 3"),
    (["b", "0"], "the following arguments are required: y"),
    (["b", "0", "0", "--color", "reddish"], "reddish"),
])
def test_bad_arguments_exit_2_with_a_reason(capsys, argv, message):
    with pytest.raises(SystemExit) as exit_info:
        parse_args(argv)
    assert exit_info.value.code == 2
    assert message in capsys.readouterr().err
