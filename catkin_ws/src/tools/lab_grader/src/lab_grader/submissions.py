"""Finding what students handed in: one submission per student, as a typed `Submission`.

A submission is either
- a folder holding at least one catkin package (a `package.xml` somewhere inside: the package itself, a folder of
  packages or a whole catkin workspace); its student id is the folder's name; or
- a `.zip`, `.tar.gz` or `.tgz` of such a folder; its id is the file name without the suffix, and it is extracted
  (safely, see `archives`) into `<work_dir>/<id>`.

`load_submission(path, work_dir)` reads exactly one. `find_submissions(path, work_dir)` also accepts a class
folder (one folder or archive per student) and guesses which of the two it was given: an archive, or a folder
with a `package.xml` or a `src` folder at its top, is one submission; any other folder is a class folder. (A
student folder whose packages sit directly in it, `alice/pkg_a/package.xml`, looks exactly like a class folder:
use `load_submission` for it.) In a class folder, one bad submission does not stop the others: it is listed in
`SubmissionScan.rejected` with its reason. Hidden entries (a leading `.`, such as `.DS_Store`) are skipped; any
other entry that is not a submission (a stray file, a `__MACOSX` folder) is rejected with its reason.

Student ids become folder names, user-visible labels and command arguments, so only letters, digits, `.`, `_`
and `-` are accepted, at most `MAX_STUDENT_ID_CHARS`, not starting with `.` or `-` (hidden files, options).
Package names are read from each `package.xml` the way catkin finds them: not below another package, not in
hidden folders, build outputs (`BUILD_OUTPUT_DIRS`) or folders holding a `CATKIN_IGNORE` file.
"""
import os
import re
import xml.etree.ElementTree as ElementTree
from pathlib import Path
from typing import List, NamedTuple, Tuple

from lab_grader.archives import ArchiveError, ArchiveLimits, archive_kind, archive_stem, extract_archive
from lab_grader.errors import GraderError

__all__ = ["ArchiveLimits", "Submission", "SubmissionError", "SubmissionScan", "find_submissions",
           "load_submission", "check_student_id"]

STUDENT_ID_PATTERN = re.compile(r"[A-Za-z0-9._-]+")
MAX_STUDENT_ID_CHARS = 64
# REP 144 asks for lower case; catkin only warns about capitals, so they are accepted. Nothing else is: package
# names end up in commands (rosrun <pkg> <node>).
PACKAGE_NAME_PATTERN = re.compile(r"[A-Za-z][A-Za-z0-9_]*")
PACKAGE_XML = "package.xml"
MAX_PACKAGE_XML_BYTES = 1024 * 1024
CATKIN_IGNORE = "CATKIN_IGNORE"
# A workspace's build outputs hold copies of package.xml files (install/share/<pkg>/package.xml).
BUILD_OUTPUT_DIRS = frozenset({"build", "devel", "install", "logs", "build_isolated", "devel_isolated"})


class SubmissionError(GraderError):
    """One submission cannot be graded. `student_id` is the id, or the file name when no valid id was found."""

    def __init__(self, student_id: str, reason: str):
        super().__init__("submission {!r}: {}".format(student_id, reason))
        self.student_id = student_id
        self.reason = reason


class Submission(NamedTuple):
    student_id: str
    source_dir: Path  # the folder to build: the student's own folder, or the archive's extraction folder
    packages: Tuple[str, ...]  # names of the catkin packages inside, sorted
    origin: Path  # the folder or archive it came from


class SubmissionScan(NamedTuple):
    submissions: List[Submission]  # sorted by student id
    rejected: List[SubmissionError]  # in the order found, each with its reason


def check_student_id(student_id: str) -> str:
    """The id itself, or SubmissionError saying what is wrong with it."""
    if not STUDENT_ID_PATTERN.fullmatch(student_id):
        raise SubmissionError(student_id, "invalid student id: only letters, digits, '.', '_' and '-' are allowed")
    if len(student_id) > MAX_STUDENT_ID_CHARS:
        raise SubmissionError(student_id, "invalid student id: longer than {} characters".format(
            MAX_STUDENT_ID_CHARS))
    if student_id[0] in ".-":
        raise SubmissionError(student_id, "invalid student id: it must not start with '.' or '-'")
    return student_id


def load_submission(path: Path, work_dir: Path, limits: ArchiveLimits = ArchiveLimits()) -> Submission:
    """Exactly one submission from a folder or an archive (extracted into `work_dir/<id>`); SubmissionError
    otherwise."""
    path = Path(path)
    if path.is_dir():
        student_id = check_student_id(path.name)
        source_dir = path
    elif path.is_file() and archive_kind(path) is not None:
        student_id = check_student_id(archive_stem(path))
        source_dir = Path(work_dir) / student_id
        Path(work_dir).mkdir(parents=True, exist_ok=True)
        try:
            extract_archive(path, source_dir, limits)
        except ArchiveError as error:
            raise SubmissionError(student_id, "{}: {}".format(path.name, error)) from None
    elif path.exists():
        raise SubmissionError(path.name, "not a submission: expected a folder holding a catkin package, or a "
                                         ".zip, .tar.gz or .tgz of one")
    else:
        raise SubmissionError(path.name, "{} does not exist".format(path))
    return Submission(student_id, source_dir, find_package_names(student_id, source_dir), path)


def find_submissions(path: Path, work_dir: Path, limits: ArchiveLimits = ArchiveLimits()) -> SubmissionScan:
    """Every submission under `path` (one submission, or a class folder of them), see the module docstring.
    Raises SubmissionError only when `path` itself does not exist; each bad submission is in `rejected`."""
    path = Path(path)
    if not path.exists():
        raise SubmissionError(path.name, "{} does not exist".format(path))
    if not path.is_dir() or is_single_submission(path):
        candidates = [path]
    else:
        candidates = sorted(entry for entry in path.iterdir() if not entry.name.startswith("."))
    submissions, rejected, seen = [], [], {}
    for candidate in candidates:
        candidate_id = archive_stem(candidate) if candidate.is_file() else candidate.name
        if candidate_id in seen:
            rejected.append(SubmissionError(candidate_id, "{} and {} both claim this student id".format(
                seen[candidate_id].name, candidate.name)))
            continue
        seen[candidate_id] = candidate
        try:
            submissions.append(load_submission(candidate, work_dir, limits))
        except SubmissionError as error:
            rejected.append(error)
    return SubmissionScan(sorted(submissions, key=lambda submission: submission.student_id), rejected)


def is_single_submission(folder: Path) -> bool:
    """A package (package.xml at its top) or a catkin workspace (a src folder at its top)."""
    return (folder / PACKAGE_XML).is_file() or (folder / "src").is_dir()


def find_package_names(student_id: str, source_dir: Path) -> Tuple[str, ...]:
    """Names of the catkin packages in `source_dir`, sorted; SubmissionError when there are none, a package.xml is
    unreadable, or two packages share a name. Symlinks are not followed."""
    names = {}
    for folder, subfolders, files in os.walk(source_dir):
        if PACKAGE_XML in files:
            subfolders.clear()  # catkin does not look for packages inside a package
            package_xml = Path(folder) / PACKAGE_XML
            name = read_package_name(student_id, package_xml, source_dir)
            if name in names:
                raise SubmissionError(student_id, "two packages are named {}: {} and {}".format(
                    name, names[name], package_xml.relative_to(source_dir)))
            names[name] = package_xml.relative_to(source_dir)
            continue
        if CATKIN_IGNORE in files:
            subfolders.clear()
            continue
        subfolders[:] = sorted(sub for sub in subfolders if not sub.startswith(".") and sub not in BUILD_OUTPUT_DIRS)
    if not names:
        raise SubmissionError(student_id, "no catkin package inside (no package.xml found)")
    return tuple(sorted(names))


def read_package_name(student_id: str, package_xml: Path, source_dir: Path) -> str:
    """The <name> of one package.xml. The file is untrusted: its size is bounded before parsing (and Python's
    expat refuses entity-expansion bombs)."""
    where = package_xml.relative_to(source_dir)
    if package_xml.is_symlink() or not package_xml.is_file():
        raise SubmissionError(student_id, "{} is not a regular file".format(where))
    if package_xml.stat().st_size > MAX_PACKAGE_XML_BYTES:
        raise SubmissionError(student_id, "{} is larger than {} bytes".format(where, MAX_PACKAGE_XML_BYTES))
    try:
        root = ElementTree.parse(package_xml).getroot()
    except (ElementTree.ParseError, UnicodeDecodeError) as error:
        raise SubmissionError(student_id, "{} is not valid XML: {}".format(where, error)) from None
    name_element = root.find("name") if root.tag == "package" else None
    name = (name_element.text or "").strip() if name_element is not None else ""
    if not name:
        raise SubmissionError(student_id, "{} has no <package><name>".format(where))
    if not PACKAGE_NAME_PATTERN.fullmatch(name):
        raise SubmissionError(student_id, "{}: invalid package name {!r} (a letter, then letters, digits or "
                                          "'_')".format(where, name))
    return name
