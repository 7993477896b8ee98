"""Hostile or broken archives are refused with the submission's id and the reason, naming the offending member,
and leave nothing behind: no extraction folder, and nothing written outside the work dir."""
import tarfile

import pytest

from lab_grader.archives import ArchiveLimits
from lab_grader.submissions import SubmissionError, load_submission

from .archive_builders import make_tar, make_zip, package_files, tar_entry, tar_file

PACKAGE = package_files("pkg")
SMALL_LIMITS = ArchiveLimits(max_bytes=64 * 1024, max_files=20)

TAR_CASES = {
    "absolute_path": ([tar_file("/tmp/lab_grader_escape", "x")], "absolute path"),
    "dot_dot": ([tar_file("src/../../escape", "x")], "'..' in the path"),
    "symlink_absolute": ([tar_entry("src/etc", tarfile.SYMTYPE, "/etc")], "points outside"),
    "symlink_up_and_out": ([tar_entry("src/up", tarfile.SYMTYPE, "../../outside")], "points outside"),
    "symlink_chain_out": ([tar_entry("a/b", tarfile.SYMTYPE, ".."), tar_entry("c", tarfile.SYMTYPE, "a/b/..")],
                          "resolves to"),
    "write_through_symlink": ([tar_entry("src", tarfile.SYMTYPE, "."), tar_file("src/escape", "x")],
                              "written through the symlink src"),
    "hard_link": ([tar_entry("passwd", tarfile.LNKTYPE, "/etc/passwd")], "hard link is not allowed"),
    "char_device": ([tar_entry("dev_null", tarfile.CHRTYPE)], "device is not allowed"),
    "block_device": ([tar_entry("disk", tarfile.BLKTYPE)], "device is not allowed"),
    "fifo": ([tar_entry("pipe", tarfile.FIFOTYPE)], "fifo is not allowed"),
    "duplicate_member": ([tar_file("notes.txt", "first"), tar_file("notes.txt", "second")], "appears twice"),
    "file_over_folder": ([tar_file("src", "x"), tar_file("src/inner", "y")], "is a file, not a folder"),
    "backslash": ([tar_file("..\\..\\escape", "x")], "backslash"),
    "too_many_files": ([tar_file("f{}".format(i), "x") for i in range(25)], "more than 20 entries"),
    "too_large": ([tar_file("zeros.bin", b"\0" * (128 * 1024))], "more than 65536 bytes"),
}


@pytest.mark.parametrize("case", sorted(TAR_CASES))
def test_an_unsafe_tar_is_refused_with_its_reason(tmp_path, case):
    members, reason = TAR_CASES[case]
    archive = make_tar(tmp_path / "mallory.tar.gz", [tar_file(n, t) for n, t in PACKAGE.items()] + members)
    work = tmp_path / "work"
    with pytest.raises(SubmissionError, match=reason) as error:
        load_submission(archive, work, SMALL_LIMITS)
    assert error.value.student_id == "mallory" and "mallory.tar.gz" in str(error.value)
    assert list(work.iterdir()) == [], "the partial extraction is removed"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["mallory.tar.gz", "work"], "nothing escaped"


ZIP_CASES = {
    "absolute_path": ({"/tmp/lab_grader_escape": "x"}, {}, "absolute path"),
    "dot_dot": ({"../escape": "x"}, {}, "'..' in the path"),
    "symlink_absolute": ({}, {"etc": "/etc"}, "points outside"),
    "symlink_up_and_out": ({}, {"src/up": "../../outside"}, "points outside"),
    "too_many_files": ({"f{}".format(i): "x" for i in range(25)}, {}, "it has 28 entries, more than the 20"),
    "too_large": ({"zeros.bin": "\0" * (128 * 1024)}, {}, "unpacks to 131.* bytes, more than the 65536"),
}


@pytest.mark.parametrize("case", sorted(ZIP_CASES))
def test_an_unsafe_zip_is_refused_with_its_reason(tmp_path, case):
    files, symlinks, reason = ZIP_CASES[case]
    archive = make_zip(tmp_path / "mallory.zip", {**PACKAGE, **files}, symlinks)
    with pytest.raises(SubmissionError, match=reason):
        load_submission(archive, tmp_path / "work", SMALL_LIMITS)
    assert list((tmp_path / "work").iterdir()) == []
    assert sorted(p.name for p in tmp_path.iterdir()) == ["mallory.zip", "work"]


def test_a_zip_that_understates_its_sizes_is_refused_without_inflating_the_rest(tmp_path):
    """A zip bomb that declares tiny sizes passes the size check on the central directory, but decompression stops
    at the declared size and the checksum then fails."""
    archive = make_zip(tmp_path / "bomb.zip", {**PACKAGE, "zeros.bin": "\0" * (256 * 1024)})
    data = bytearray(archive.read_bytes())
    real_size = (256 * 1024).to_bytes(4, "little")
    data = data.replace(real_size, (10).to_bytes(4, "little"))  # local header and central directory both lie
    archive.write_bytes(bytes(data))
    with pytest.raises(SubmissionError, match="not a readable zip archive: Bad CRC-32 for file 'zeros.bin'"):
        load_submission(archive, tmp_path / "work", SMALL_LIMITS)
    assert list((tmp_path / "work").iterdir()) == []


@pytest.mark.parametrize("content, suffix", [(b"not a zip at all", ".zip"), (b"\x1f\x8b\x08garbage", ".tgz"),
                                             (b"", ".tar.gz")])
def test_a_corrupt_archive_is_refused_without_a_traceback(tmp_path, content, suffix):
    archive = tmp_path / ("oscar" + suffix)
    archive.write_bytes(content)
    with pytest.raises(SubmissionError, match="not a readable"):
        load_submission(archive, tmp_path / "work")
    assert list((tmp_path / "work").iterdir()) == []


def test_a_truncated_tar_is_refused(tmp_path):
    archive = make_tar(tmp_path / "pat.tgz", [tar_file(n, t) for n, t in PACKAGE.items()])
    archive.write_bytes(archive.read_bytes()[:60])
    with pytest.raises(SubmissionError, match="not a readable tar archive"):
        load_submission(archive, tmp_path / "work")
