"""The sweep folder under ~/myrosdata/action_examples/, image names and the result's image_path texts."""
import datetime
from pathlib import Path

import pytest

from week5_actions.image_folder import (
    MAX_SAME_SECOND_FOLDERS,
    aborted_text,
    display_path,
    image_file_name,
    new_sweep_folder,
    preempted_text,
)

STARTED = datetime.datetime(2025, 3, 7, 14, 5, 9)


def test_the_folder_is_named_after_the_start_time(tmp_path):
    folder = new_sweep_folder(tmp_path, STARTED)
    assert folder == tmp_path / "myrosdata" / "action_examples" / "20250307_140509"
    assert folder.is_dir()


def test_a_second_sweep_in_the_same_second_gets_its_own_folder(tmp_path):
    first = new_sweep_folder(tmp_path, STARTED)
    (first / "img001.jpg").write_bytes(b"first")
    second = new_sweep_folder(tmp_path, STARTED)
    third = new_sweep_folder(tmp_path, STARTED)
    assert (second.name, third.name) == ("20250307_140509_2", "20250307_140509_3")
    assert (first / "img001.jpg").read_bytes() == b"first"


def test_too_many_folders_in_one_second_is_an_error(tmp_path):
    for _ in range(MAX_SAME_SECOND_FOLDERS):
        new_sweep_folder(tmp_path, STARTED)
    with pytest.raises(FileExistsError, match="100 sweep folders"):
        new_sweep_folder(tmp_path, STARTED)


def test_an_unwritable_home_is_an_os_error(tmp_path):
    (tmp_path / "myrosdata").write_text("a file where the folder should be")
    with pytest.raises(OSError):
        new_sweep_folder(tmp_path, STARTED)


@pytest.mark.parametrize("number, name", [(1, "img001.jpg"), (12, "img012.jpg"), (50, "img050.jpg")])
def test_image_names(number, name):
    assert image_file_name(number) == name


def test_paths_in_home_are_shown_with_a_tilde():
    home = Path("/home/student")
    assert display_path(home / "myrosdata/action_examples/20250307_140509", home) == \
        "~/myrosdata/action_examples/20250307_140509"
    assert display_path(Path("/tmp/elsewhere"), home) == "/tmp/elsewhere"


def test_preempted_and_aborted_texts():
    assert preempted_text("~/myrosdata/x", 2, 4) == "~/myrosdata/x [PRE-EMPTED at image 2 of 4]"
    assert aborted_text("image_count 0 is not in 1..50") == "None [ABORTED: image_count 0 is not in 1..50]"
    assert aborted_text("the camera stopped", "~/f", 0) == "None [ABORTED: the camera stopped]"
    assert aborted_text("the camera stopped", "~/f", 1) == "None [ABORTED: the camera stopped (1 image saved in ~/f)]"
    assert aborted_text("no /odom", "~/f", 3) == "None [ABORTED: no /odom (3 images saved in ~/f)]"
