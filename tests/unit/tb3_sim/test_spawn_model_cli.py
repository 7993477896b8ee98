"""gazebo_ros-style spawn_model arguments -> the SpawnModel request (no master needed)."""
import math

import pytest

from tb3_sim.tools.spawn_model import parser, read_model, spawn_request


def test_turtlebot3_launch_style_arguments(tmp_path):
    model = tmp_path / "box.sdf"
    model.write_text("<sdf/>")
    args = parser().parse_args(["-sdf", "-model", "box1", "-file", str(model), "-x", "-1.5", "-y", "0.5",
                                "-z", "0.1", "-Y", "1.0", "-J", "joint", "0.3", "-unpause"])
    assert read_model(args) == "<sdf/>"
    request = spawn_request(args, "<sdf/>")
    assert request.model_name == "box1"
    assert (request.initial_pose.position.x, request.initial_pose.position.y) == (-1.5, 0.5)
    assert 2 * math.atan2(request.initial_pose.orientation.z, request.initial_pose.orientation.w) == \
        pytest.approx(1.0)
    assert args.unpause and args.sdf and not args.urdf


@pytest.mark.parametrize("argv, message", [
    (["-model", "m", "-file", "f"], "one of the arguments -urdf -sdf is required"),
    (["-sdf", "-file", "f"], "the following arguments are required: -model"),
    (["-sdf", "-urdf", "-model", "m", "-file", "f"], "not allowed with argument"),
])
def test_bad_arguments_exit_2(capsys, argv, message):
    with pytest.raises(SystemExit) as exit_info:
        parser().parse_args(argv)
    assert exit_info.value.code == 2
    assert message in capsys.readouterr().err


def test_missing_file_and_database_are_clear_errors(tmp_path):
    args = parser().parse_args(["-sdf", "-model", "m", "-file", str(tmp_path / "none.sdf")])
    with pytest.raises(ValueError, match="cannot read .*none.sdf: No such file"):
        read_model(args)
    args = parser().parse_args(["-sdf", "-model", "m", "-database", "coke_can"])
    with pytest.raises(ValueError, match="-database is not supported"):
        read_model(args)
