"""The course worlds' tb3_sim world files (tuos_simulations, com2009_simulations) load, name their static models as
the originals' /gazebo/model_states does, and carry a floor where the original has a floor texture; every launch
file that loads a world names one of them."""
import re
from pathlib import Path

import pytest

from tb3_sim.core.world_file import load_world

COMPAT = Path(__file__).resolve().parents[3] / "catkin_ws" / "src" / "compat"
STATIC_MODELS = {
    "tuos_simulations/navigation": ["navigation", "arena_walls"],
    "tuos_simulations/line_following_setup": ["line_following_setup"],
    "tuos_simulations/line_following": ["line_following_track"],
    "tuos_simulations/coloured_pillars": ["turtlebot3_square", "obstacle"],   # on Gazebo's plain ground plane
    "com2009_simulations/cr5_empty_arena": ["cr5_arena_floor", "cr5_arena_walls"],
    "com2009_simulations/task1": ["obstacle_avoidance", "cr5_arena_walls"],
    "com2009_simulations/task2": ["task2", "cr5_arena_walls"],
    "com2009_simulations/maze": ["arena_walls", "task3_maze"],
    "com2009_simulations/task3b": ["arena_walls", "task3b"],
    "com2009_simulations/exploration": ["task4_explore", "cr5_arena_walls"],
}
WORLD_FILE = re.compile(r"\$\(find (\w+)\)/worlds/(\w+)\.yaml")


def world_path(key):
    package, name = key.split("/")
    return COMPAT / package / "worlds" / f"{name}.yaml"


def test_every_world_file_is_listed():
    found = {f"{p.parent.parent.name}/{p.stem}" for p in COMPAT.glob("*_simulations/worlds/*.yaml")}
    assert found == set(STATIC_MODELS)


@pytest.mark.parametrize("key", sorted(STATIC_MODELS))
def test_world_loads_with_the_originals_model_names_and_its_floor(key):
    world = load_world(world_path(key))
    assert list(world.static_model_names) == STATIC_MODELS[key]
    assert (world.floor is None) == (key == "tuos_simulations/coloured_pillars")


def test_every_world_launch_file_names_a_world_file_of_its_package():
    launch_files = sorted(COMPAT.glob("*_simulations/launch/*.launch"))
    worlds = [WORLD_FILE.search(p.read_text()) for p in launch_files if p.name != "rviz.launch"]
    assert len(worlds) == 11 and all(worlds)
    for launch_file, match in zip([p for p in launch_files if p.name != "rviz.launch"], worlds):
        assert match.group(1) == launch_file.parent.parent.name
        assert world_path(f"{match.group(1)}/{match.group(2)}").is_file()
