"""The grader's trajectory picture draws the world's floor markings, walls and the trajectories."""
from pathlib import Path

import cv2
import numpy as np

from lab_grader import trajectory_picture

FLOOR_WORLD = Path(__file__).parents[1] / "tb3_sim" / "fixtures" / "floor_worlds" / "every_marking.yaml"
CHECKS = [{"id": "drive", "verdict": "pass", "evidence": {"trajectory": [[0, 0, 0, 0], [1, 1, 0, 0]]}}]


def _magenta_pixels(png):
    bgr = cv2.imdecode(np.frombuffer(png, np.uint8), cv2.IMREAD_COLOR).astype(int)
    return int(((bgr[..., 2] > 200) & (bgr[..., 0] > 200) & (bgr[..., 1] < 60)).sum())


def test_the_picture_shows_the_floor_markings(monkeypatch):
    monkeypatch.setattr(trajectory_picture, "world_path", lambda name: FLOOR_WORLD)
    assert _magenta_pixels(trajectory_picture.trajectory_png("every_marking", CHECKS)) > 500


def test_a_world_in_another_package_is_drawn_by_its_package_path():
    """The course's line-following track (tuos_simulations) and its pink line."""
    png = trajectory_picture.trajectory_png("tuos_simulations/worlds/line_following.yaml", CHECKS)
    assert _magenta_pixels(png) > 500


def test_a_world_without_a_floor_layer_still_draws():
    png = trajectory_picture.trajectory_png("turtlebot3_world", CHECKS)
    assert png.startswith(b"\x89PNG") and _magenta_pixels(png) == 0
