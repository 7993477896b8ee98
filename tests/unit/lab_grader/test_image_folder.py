"""The images a result names: "~" is the student's home, the folder must stay inside it, links are not followed,
image files are counted and decoded with OpenCV; every problem is a sentence."""
import os

import cv2
import numpy

from lab_grader.checks.image_folder import folder_in_home, inspect


def write_jpeg(path):
    ok, data = cv2.imencode(".jpg", numpy.full((48, 64, 3), 128, numpy.uint8))
    assert ok
    path.write_bytes(data.tobytes())


def test_the_course_folder_with_four_images_is_found_and_decoded(tmp_path):
    folder = tmp_path / "myrosdata" / "action_examples" / "20250101_120000"
    folder.mkdir(parents=True)
    for number in range(1, 5):
        write_jpeg(folder / "img{:03d}.jpg".format(number))
    (folder / "notes.txt").write_text("not an image")
    found = inspect("~/myrosdata/action_examples/20250101_120000", tmp_path)
    assert found.problem is None
    assert found.images == found.decodable == ("img001.jpg", "img002.jpg", "img003.jpg", "img004.jpg")


def test_a_note_after_the_folder_is_ignored_and_a_broken_image_does_not_decode(tmp_path):
    (tmp_path / "sweep").mkdir()
    write_jpeg(tmp_path / "sweep" / "img001.jpg")
    (tmp_path / "sweep" / "img002.jpg").write_bytes(b"\xff\xd8 truncated")
    found = inspect("~/sweep [PRE-EMPTED at image 2 of 4]", tmp_path)
    assert found.images == ("img001.jpg", "img002.jpg") and found.decodable == ("img001.jpg",)


def test_folders_outside_the_home_and_links_out_are_refused(tmp_path):
    home = tmp_path / "home"
    home.mkdir()
    outside = tmp_path / "secret"
    outside.mkdir()
    write_jpeg(outside / "img001.jpg")
    os.symlink(outside, home / "link")
    assert inspect("~/../secret", home).problem == "../secret is outside the student's home folder"
    assert inspect("~/link", home).problem == "link is outside the student's home folder"
    assert inspect("/etc", home).problem == "/etc is outside the student's home folder"
    (home / "sweep").mkdir()
    os.symlink(outside / "img001.jpg", home / "sweep" / "img001.jpg")
    assert inspect("~/sweep", home).images == ()


def test_missing_folders_and_paths_are_named(tmp_path):
    assert inspect("~/nowhere", tmp_path).problem == "cannot read the folder: No such file or directory"
    assert inspect("None [ABORTED: no]", tmp_path).problem == "cannot read the folder: No such file or directory"
    assert inspect(None, tmp_path).problem == "the result has no image folder path"
    assert inspect("~/x", None).problem == "the student's home folder is not known (run_checks --student-home)"
    assert inspect("", tmp_path).problem == "the result names no folder"
    assert folder_in_home("~", tmp_path) == tmp_path.resolve()
