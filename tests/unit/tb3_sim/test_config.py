"""The node's parameters: defaults, world names and paths, and clear errors for bad values."""
import pytest

from tb3_sim.core.errors import ConfigError
from tb3_sim.core.world_file import SHIPPED_WORLDS_DIR
from tb3_sim.ros.config import config_from_params, resolve_world


def test_defaults():
    config = config_from_params({}, SHIPPED_WORLDS_DIR)
    assert config.world_path == SHIPPED_WORLDS_DIR / "empty.yaml"
    assert (config.x_pos, config.y_pos, config.yaw) == (0.0, 0.0, 0.0)
    assert config.robot_name == "turtlebot3_waffle"
    assert config.real_time_factor == 1.0
    assert (config.clock_rate, config.spawn_robot, config.model, config.robot_name) == (
        100.0, True, "waffle", "turtlebot3_waffle")
    assert (config.camera_width, config.camera_height, config.camera_rate) == (None, None, None)
    assert not config.paused and not config.headless and config.publish_static_tf
    assert config.snapshot_path == "/tmp/tb3_sim.png"


def test_values_from_a_launch_file_are_typed():
    config = config_from_params({"world": "turtlebot3_world", "x_pos": -2, "y_pos": -0.5, "seed": 7,
                                 "real_time_factor": 0, "paused": True}, SHIPPED_WORLDS_DIR)
    assert config.world_path.name == "turtlebot3_world.yaml"
    assert (config.x_pos, config.y_pos, config.seed, config.real_time_factor) == (-2.0, -0.5, 7, 0.0)
    assert config.paused


def test_world_by_path(tmp_path):
    path = tmp_path / "mine.yaml"
    path.write_text("name: mine\n")
    assert resolve_world(str(path), SHIPPED_WORLDS_DIR) == path


def test_unknown_world_lists_the_shipped_ones():
    shipped = ", ".join(sorted(path.stem for path in SHIPPED_WORLDS_DIR.glob("*.yaml")))
    assert "approach_arena, colour_search, empty, fruit_world" in shipped
    with pytest.raises(ConfigError, match=rf"no world file .*nowhere\.yaml.*{shipped}"):
        resolve_world("nowhere", SHIPPED_WORLDS_DIR)


@pytest.mark.parametrize("params, message", [
    ({"x_pos": "left"}, r"~x_pos must be a finite number, got 'left'"),
    ({"yaw": float("nan")}, r"~yaw must be a finite number"),
    ({"real_time_factor": -1}, r"~real_time_factor must be >= 0.0, got -1"),
    ({"clock_rate": -5}, r"~clock_rate must be >= 0.0, got -5"),
    ({"model": "wafle"}, r"~model must be one of burger, waffle, waffle_pi, got 'wafle'"),
    ({"spawn_robot": "no"}, r"~spawn_robot must be true or false, got 'no'"),
    ({"seed": 1.5}, r"~seed must be an integer, got 1.5"),
    ({"paused": "yes"}, r"~paused must be true or false, got 'yes'"),
    ({"robot_name": "my robot"}, r"~robot_name must be a non-empty string without spaces"),
    ({"world": ""}, r"~world must be a world name or a file path"),
])
def test_bad_values_name_the_parameter(params, message):
    with pytest.raises(ConfigError, match=message):
        config_from_params(params, SHIPPED_WORLDS_DIR)
