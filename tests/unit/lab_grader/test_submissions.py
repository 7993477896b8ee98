"""Finding submissions: a package folder, a workspace folder, a .zip, a .tar.gz or .tgz, and a class folder of
them all (sorted, with each bad entry listed with its reason instead of stopping the others); package names read
from package.xml the way catkin finds them; student ids checked."""
import os
import stat
import tarfile

import pytest

from lab_grader.submissions import SubmissionError, find_submissions, load_submission

from .archive_builders import make_tar, make_zip, package_files, tar_entry, tar_file, write_folder


def test_a_folder_holding_a_package_is_one_submission_named_after_the_folder(tmp_path):
    folder = write_folder(tmp_path / "alice", package_files("talker"))
    scan = find_submissions(folder, tmp_path / "work")
    assert scan.rejected == []
    [submission] = scan.submissions
    assert submission.student_id == "alice" and submission.packages == ("talker",)
    assert submission.source_dir == folder and submission.origin == folder
    assert not (tmp_path / "work").exists(), "a folder is graded where it is, nothing is copied"


def test_a_workspace_folder_lists_every_package_once_and_skips_build_outputs_and_ignored_folders(tmp_path):
    files = {**package_files("pkg_b", "src/pkg_b/"), **package_files("pkg_a", "src/group/pkg_a/"),
             **package_files("pkg_a", "install/share/pkg_a/"), **package_files("hidden", "src/.git/hidden/"),
             **package_files("ignored", "src/old/ignored/"), "src/old/CATKIN_IGNORE": "",
             **package_files("inner", "src/pkg_b/test/inner/")}
    folder = write_folder(tmp_path / "bob_ws", files)
    [submission] = find_submissions(folder, tmp_path / "work").submissions
    assert submission.student_id == "bob_ws" and submission.packages == ("pkg_a", "pkg_b")


@pytest.mark.parametrize("suffix", [".zip", ".tar.gz", ".tgz", ".ZIP"])
def test_an_archive_is_extracted_into_the_work_dir_and_named_after_the_file(tmp_path, suffix):
    files = package_files("listener", "carol_ws/src/listener/")
    archive = tmp_path / ("carol" + suffix)
    if suffix.lower() == ".zip":
        make_zip(archive, files, modes={"carol_ws/src/listener/scripts/node.py": 0o755})
    else:
        make_tar(archive, [tar_file(name, text, 0o755 if name.endswith(".py") else 0o644)
                           for name, text in files.items()])
    submission = load_submission(archive, tmp_path / "work")
    assert submission.student_id == "carol" and submission.packages == ("listener",)
    assert submission.source_dir == tmp_path / "work" / "carol" and submission.origin == archive
    node = submission.source_dir / "carol_ws/src/listener/scripts/node.py"
    assert node.read_text().startswith("#!/usr/bin/env python3")
    assert stat.S_IMODE(node.stat().st_mode) == 0o755
    assert stat.S_IMODE((submission.source_dir / "carol_ws/src/listener/package.xml").stat().st_mode) == 0o644


def test_setuid_and_world_writable_bits_are_dropped(tmp_path):
    archive = make_tar(tmp_path / "dan.tgz", [tar_file(name, text, 0o6777) for name, text in
                                              package_files("dan_pkg").items()])
    submission = load_submission(archive, tmp_path / "work")
    modes = {stat.S_IMODE(path.stat().st_mode) for path in submission.source_dir.rglob("*") if path.is_file()}
    assert modes == {0o755}


def test_symlinks_inside_the_submission_are_kept(tmp_path):
    files = package_files("eve_pkg", "src/eve_pkg/")
    archive = make_zip(tmp_path / "eve.zip", files, symlinks={"src/link_to_pkg": "eve_pkg",
                                                              "src/eve_pkg/up": "../eve_pkg/scripts"})
    submission = load_submission(archive, tmp_path / "work")
    assert os.readlink(submission.source_dir / "src/link_to_pkg") == "eve_pkg"
    assert (submission.source_dir / "src/eve_pkg/up/node.py").is_file()
    assert submission.packages == ("eve_pkg",), "symlinked packages are not counted twice"


def test_a_class_folder_of_mixed_submissions_is_sorted_and_lists_each_problem(tmp_path):
    class_dir = tmp_path / "class"
    write_folder(class_dir / "zoe", package_files("zoe_pkg", "src/zoe_pkg/"))
    make_zip(class_dir / "bob.zip", package_files("bob_pkg"))
    make_tar(class_dir / "carol.tar.gz", [tar_file(n, t) for n, t in package_files("carol_pkg", "ws/").items()])
    make_tar(class_dir / "dan.tgz", [tar_file(n, t) for n, t in package_files("dan_pkg").items()])
    make_zip(class_dir / "eve smith.zip", package_files("eve_pkg"))
    make_zip(class_dir / "fay.zip", {"README.md": "I ran out of time"})
    (class_dir / "grades.csv").write_text("id,grade\n")
    (class_dir / ".DS_Store").write_text("")
    write_folder(class_dir / "bob", package_files("bob_pkg"))

    scan = find_submissions(class_dir, tmp_path / "work")

    assert [(s.student_id, s.packages) for s in scan.submissions] == [
        ("bob", ("bob_pkg",)), ("carol", ("carol_pkg",)), ("dan", ("dan_pkg",)), ("zoe", ("zoe_pkg",))]
    reasons = {error.student_id: error.reason for error in scan.rejected}
    assert set(reasons) == {"bob", "eve smith", "fay", "grades.csv"}
    assert "both claim this student id" in reasons["bob"] and "bob.zip" in reasons["bob"]
    assert "invalid student id" in reasons["eve smith"]
    assert "no package.xml" in reasons["fay"]
    assert "not a submission" in reasons["grades.csv"]
    assert all(str(error).startswith("submission {!r}: ".format(error.student_id)) for error in scan.rejected)


def test_an_empty_class_folder_finds_nothing(tmp_path):
    (tmp_path / "class").mkdir()
    assert find_submissions(tmp_path / "class", tmp_path / "work") == ([], [])


def test_a_missing_path_is_an_error_naming_it(tmp_path):
    with pytest.raises(SubmissionError, match="does not exist"):
        find_submissions(tmp_path / "nowhere", tmp_path / "work")


def test_extracting_twice_into_the_same_work_dir_is_refused_and_keeps_the_first(tmp_path):
    archive = make_zip(tmp_path / "gus.zip", package_files("gus_pkg"))
    load_submission(archive, tmp_path / "work")
    with pytest.raises(SubmissionError, match="already exists"):
        load_submission(archive, tmp_path / "work")
    assert (tmp_path / "work" / "gus" / "package.xml").is_file()


@pytest.mark.parametrize("files, reason", [
    ({"README.md": "nothing"}, "no package.xml"),
    ({"package.xml": "<package><name>x</name>"}, "not valid XML"),
    ({"package.xml": "<package><version>1</version></package>"}, "has no <package><name>"),
    ({"package.xml": "<package><name>bad-name; rm -rf /</name></package>"}, "invalid package name"),
    ({"a/package.xml": "<package><name>twin</name></package>",
      "b/package.xml": "<package><name>twin</name></package>"}, "two packages are named twin"),
    ({"package.xml": "<!DOCTYPE p [<!ENTITY a '{}'>]><package><name>&a;</name></package>".format("x" * 2_000_000)},
     "larger than"),
], ids=["no_package", "broken_xml", "no_name", "bad_name", "duplicate_package", "huge_package_xml"])
def test_a_folder_without_a_usable_package_is_refused_with_the_reason(tmp_path, files, reason):
    folder = write_folder(tmp_path / "hal", files)
    with pytest.raises(SubmissionError, match=reason) as error:
        load_submission(folder, tmp_path / "work")
    assert error.value.student_id == "hal"


@pytest.mark.parametrize("student_id", ["alice", "Bob_Smith-2", "c.d", "u1234567", "x" * 64])
def test_ids_of_letters_digits_dots_underscores_and_dashes_are_accepted(tmp_path, student_id):
    folder = write_folder(tmp_path / student_id, package_files("pkg"))
    assert load_submission(folder, tmp_path / "work").student_id == student_id


@pytest.mark.parametrize("student_id, reason", [
    ("eve smith", "only letters, digits"), ("a$b", "only letters, digits"), ("zoë", "only letters, digits"),
    ("a;b", "only letters, digits"), ("-rf", "must not start"), (".hidden", "must not start"),
    ("x" * 65, "longer than 64"),
])
def test_other_ids_are_refused(tmp_path, student_id, reason):
    archive = make_zip(tmp_path / (student_id + ".zip"), package_files("pkg"))
    with pytest.raises(SubmissionError, match=reason):
        load_submission(archive, tmp_path / "work")
    assert not (tmp_path / "work").exists() or list((tmp_path / "work").iterdir()) == []


def test_a_tar_directory_entry_and_its_own_top_folder_are_fine(tmp_path):
    members = [tar_entry("./", tarfile.DIRTYPE), tar_entry("ivy_ws", tarfile.DIRTYPE),
               tar_entry("ivy_ws/src", tarfile.DIRTYPE)]
    members += [tar_file(n, t) for n, t in package_files("ivy_pkg", "ivy_ws/src/ivy_pkg/").items()]
    submission = load_submission(make_tar(tmp_path / "ivy.tgz", members), tmp_path / "work")
    assert submission.packages == ("ivy_pkg",)
