"""Safe extraction of a student's .zip, .tar.gz or .tgz.

An archive is untrusted input unpacked by the grader, which runs as root: a member named `/etc/cron.d/x` or
`../../x`, a symlink to `/` followed by a member written "through" it, a device node, or a few kilobytes that
inflate to gigabytes would all hurt the machine. So every member is checked before anything is written:

- names: relative, no `..` component, no backslash, each part at most `MAX_NAME_PART_CHARS`;
- kinds: regular files, directories and symlinks only (no hard links, devices, fifos or sockets);
- symlinks: relative, and pointing inside the submission (judged on the name, never by following links);
- nothing is written through a symlink or over an earlier member (a name that appears twice is refused);
- totals: at most `ArchiveLimits.max_files` members and `ArchiveLimits.max_bytes` of file content, counted while
  decompressing (a member's declared size is not trusted);
- modes: files get 0644, or 0755 when any execute bit was set (no setuid, setgid or world-writable bits).

A refused archive leaves nothing behind: the destination folder is removed and an `ArchiveError` states the
reason, naming the offending member.
"""
import gzip
import os
import posixpath
import shutil
import stat
import tarfile
import zipfile
import zlib
from contextlib import contextmanager
from pathlib import Path
from typing import IO, Callable, Iterator, NamedTuple, Optional

from lab_grader.errors import GraderError

MIB = 1024 * 1024
DEFAULT_MAX_BYTES = 50 * MIB
DEFAULT_MAX_FILES = 5000
# Headers, names and padding an archive may carry per member beyond its content, in bytes: bounds the size of the
# archive file itself before it is read.
MAX_OVERHEAD_PER_MEMBER_BYTES = 1024
MAX_NAME_PART_CHARS = 255
MAX_SYMLINK_TARGET_BYTES = 4096
COPY_CHUNK_BYTES = 64 * 1024
FILE_MODE = 0o644
EXECUTABLE_FILE_MODE = 0o755
DIR_MODE = 0o755

# Suffix (lower case) -> kind. Longest first, so "x.tar.gz" is a tar archive and not a ".gz".
ARCHIVE_SUFFIXES = ((".tar.gz", "tar"), (".tgz", "tar"), (".zip", "zip"))


class ArchiveError(GraderError):
    """The archive is unreadable or unsafe; the message says which member and why."""


class ArchiveLimits(NamedTuple):
    """Bounds on what one submission archive may unpack to."""
    max_bytes: int = DEFAULT_MAX_BYTES  # total size of all files once decompressed, in bytes
    max_files: int = DEFAULT_MAX_FILES  # members of any kind (files, folders, symlinks)


class _Member(NamedTuple):
    """An archive entry, the same for zip and tar."""
    name: str
    kind: str  # "file", "dir", "symlink", or a word naming a refused kind ("hard link", "device", ...)
    executable: bool
    link_target: Optional[str]
    open: Callable[[], IO[bytes]]  # the content, for files


def archive_kind(path: Path) -> Optional[str]:
    """"zip" or "tar" from the file name (case-insensitive), None when it is not an accepted archive."""
    lower = path.name.lower()
    for suffix, kind in ARCHIVE_SUFFIXES:
        if lower.endswith(suffix) and len(lower) > len(suffix):
            return kind
    return None


def archive_stem(path: Path) -> str:
    """The file name without its archive suffix: `alice.tar.gz` -> `alice`."""
    lower = path.name.lower()
    for suffix, _ in ARCHIVE_SUFFIXES:
        if lower.endswith(suffix):
            return path.name[:-len(suffix)]
    return path.name


def extract_archive(archive: Path, dest: Path, limits: ArchiveLimits = ArchiveLimits()) -> None:
    """Unpack `archive` into the new folder `dest` (which must not exist), or raise ArchiveError and leave no
    `dest` behind."""
    kind = archive_kind(archive)
    if kind is None:
        raise ArchiveError("{} is not a .zip, .tar.gz or .tgz file".format(archive.name))
    max_archive_bytes = limits.max_bytes + limits.max_files * MAX_OVERHEAD_PER_MEMBER_BYTES
    if archive.stat().st_size > max_archive_bytes:
        raise ArchiveError("the archive is {} bytes, more than the {} allowed".format(archive.stat().st_size,
                                                                                   max_archive_bytes))
    try:
        dest.mkdir(mode=DIR_MODE)
    except FileExistsError:
        raise ArchiveError("{} already exists: extract into an empty work folder".format(dest)) from None
    try:
        opener = _zip_members if kind == "zip" else _tar_members
        with opener(archive, limits) as members:
            _Extractor(dest, limits).extract(members)
    except ArchiveError:
        shutil.rmtree(dest, ignore_errors=True)
        raise
    except (zipfile.BadZipFile, tarfile.TarError, EOFError, zlib.error, RuntimeError, NotImplementedError,
            OSError) as error:
        # Corrupt, truncated, encrypted or oddly compressed archives, and file names the file system refuses.
        shutil.rmtree(dest, ignore_errors=True)
        raise ArchiveError("not a readable {} archive: {}".format(kind, error)) from None
    except BaseException:
        shutil.rmtree(dest, ignore_errors=True)
        raise


@contextmanager
def _zip_members(archive: Path, limits: ArchiveLimits) -> Iterator[Iterator[_Member]]:
    with zipfile.ZipFile(archive) as zf:
        infos = zf.infolist()
        if len(infos) > limits.max_files:
            raise ArchiveError("it has {} entries, more than the {} allowed".format(len(infos), limits.max_files))
        declared = sum(info.file_size for info in infos)
        if declared > limits.max_bytes:
            raise ArchiveError("it unpacks to {} bytes, more than the {} allowed".format(declared, limits.max_bytes))
        yield (_zip_member(zf, info) for info in infos)


def _zip_member(zf: zipfile.ZipFile, info: zipfile.ZipInfo) -> _Member:
    mode = info.external_attr >> 16  # Unix mode bits, 0 when the archiver did not record them
    link_target = None
    if stat.S_ISLNK(mode):
        kind = "symlink"
        if info.file_size > MAX_SYMLINK_TARGET_BYTES:
            raise ArchiveError("{}: symlink target longer than {} bytes".format(info.filename,
                                                                              MAX_SYMLINK_TARGET_BYTES))
        link_target = zf.read(info).decode("utf-8", "replace")
    elif info.is_dir():
        kind = "dir"
    elif stat.S_ISCHR(mode) or stat.S_ISBLK(mode):
        kind = "device"
    elif stat.S_ISFIFO(mode):
        kind = "fifo"
    elif stat.S_ISSOCK(mode):
        kind = "socket"
    else:
        kind = "file"
    return _Member(info.filename, kind, bool(mode & 0o111), link_target, lambda: zf.open(info))


@contextmanager
def _tar_members(archive: Path, limits: ArchiveLimits) -> Iterator[Iterator[_Member]]:
    # Stream mode: each member is checked (and a bomb refused) as the decompressor reaches it, instead of inflating
    # the whole archive first to list it.
    # gzip's own reader, because tarfile's stream reader fails with a TypeError on some corrupt gzip headers.
    with gzip.open(archive, "rb") as unzipped, tarfile.open(fileobj=unzipped, mode="r|") as tar:
        yield (_tar_member(tar, info) for info in tar)


def _tar_member(tar: tarfile.TarFile, info: tarfile.TarInfo) -> _Member:
    if info.isfile():
        kind = "file"
    elif info.isdir():
        kind = "dir"
    elif info.issym():
        kind = "symlink"
    elif info.islnk():
        kind = "hard link"
    elif info.ischr() or info.isblk():
        kind = "device"
    elif info.isfifo():
        kind = "fifo"
    else:
        kind = "entry of tar type {!r}".format(info.type)
    return _Member(info.name, kind, bool(info.mode & 0o111), info.linkname if info.issym() else None,
                   lambda: tar.extractfile(info))


class _Extractor:
    """Writes checked members under `root`, keeping the running totals the limits apply to."""

    def __init__(self, root: Path, limits: ArchiveLimits):
        self.root = root
        self.limits = limits
        self.members = 0
        self.bytes = 0
        self.symlinks = []  # (member name, path) of every symlink written

    def extract(self, members: Iterator[_Member]) -> None:
        for member in members:
            self.members += 1
            if self.members > self.limits.max_files:
                raise ArchiveError("more than {} entries".format(self.limits.max_files))
            self._extract_one(member)
        self._check_symlinks_resolve_inside()

    def _check_symlinks_resolve_inside(self) -> None:
        """The name-based check cannot see chains ("a/b" -> ".." then "c" -> "a/b/.."): once everything is written,
        every symlink is resolved on disk and must still land inside."""
        root = os.path.realpath(self.root)
        for name, path in self.symlinks:
            resolved = os.path.realpath(path)
            if resolved != root and not resolved.startswith(root + os.sep):
                raise ArchiveError("{}: symlink resolves to {}, outside the submission".format(name, resolved))

    def _extract_one(self, member: _Member) -> None:
        parts = safe_parts(member.name)
        if not parts:
            return  # the archive's own top folder ("./")
        if member.kind not in ("file", "dir", "symlink"):
            raise ArchiveError("{}: a {} is not allowed in a submission".format(member.name, member.kind))
        parent = self._make_parents(member.name, parts[:-1])
        target = parent / parts[-1]
        if os.path.lexists(target):
            if member.kind == "dir" and target.is_dir() and not target.is_symlink():
                return
            raise ArchiveError("{}: appears twice in the archive".format(member.name))
        if member.kind == "dir":
            target.mkdir(mode=DIR_MODE)
        elif member.kind == "symlink":
            check_symlink(member.name, parts, member.link_target)
            os.symlink(member.link_target, target)
            self.symlinks.append((member.name, target))
        else:
            self._write_file(member, target)

    def _make_parents(self, name: str, parts: tuple) -> Path:
        """The member's folder, created where missing; refuses to pass through a symlink or a file."""
        path = self.root
        for part in parts:
            path = path / part
            try:
                mode = os.lstat(path).st_mode
            except FileNotFoundError:
                path.mkdir(mode=DIR_MODE)
                continue
            if stat.S_ISLNK(mode):
                raise ArchiveError("{}: would be written through the symlink {}".format(
                    name, path.relative_to(self.root)))
            if not stat.S_ISDIR(mode):
                raise ArchiveError("{}: {} is a file, not a folder".format(name, path.relative_to(self.root)))
        return path

    def _write_file(self, member: _Member, target: Path) -> None:
        mode = EXECUTABLE_FILE_MODE if member.executable else FILE_MODE
        fd = os.open(target, os.O_WRONLY | os.O_CREAT | os.O_EXCL | os.O_NOFOLLOW, mode)
        with os.fdopen(fd, "wb") as out, member.open() as source:
            while True:
                chunk = source.read(COPY_CHUNK_BYTES)
                if not chunk:
                    break
                self.bytes += len(chunk)
                if self.bytes > self.limits.max_bytes:
                    raise ArchiveError("{}: the archive unpacks to more than {} bytes".format(
                        member.name, self.limits.max_bytes))
                out.write(chunk)
        os.chmod(target, mode)  # exact, whatever the umask


def safe_parts(name: str) -> tuple:
    """The path parts of a member name, or ArchiveError when the name could land outside the extraction folder."""
    if "\\" in name:
        raise ArchiveError("{}: backslash in a member name".format(name))
    if "\x00" in name:
        raise ArchiveError("{!r}: NUL character in a member name".format(name))
    if name.startswith("/"):
        raise ArchiveError("{}: absolute path".format(name))
    parts = tuple(part for part in name.split("/") if part not in ("", "."))
    if ".." in parts:
        raise ArchiveError("{}: '..' in the path".format(name))
    for part in parts:
        if len(part.encode("utf-8", "surrogateescape")) > MAX_NAME_PART_CHARS:
            raise ArchiveError("{}: a name longer than {} characters".format(name[:80] + "...", MAX_NAME_PART_CHARS))
    return parts


def check_symlink(name: str, parts: tuple, link_target: Optional[str]) -> None:
    """Refuse a symlink that is absolute or whose target, read as a path, leaves the extraction folder."""
    if not link_target:
        raise ArchiveError("{}: symlink with an empty target".format(name))
    if link_target.startswith("/"):
        raise ArchiveError("{}: symlink to the absolute path {} points outside the submission".format(
            name, link_target))
    resolved = posixpath.normpath(posixpath.join(*parts[:-1], link_target) if len(parts) > 1 else link_target)
    if resolved == ".." or resolved.startswith("../"):
        raise ArchiveError("{}: symlink to {} points outside the submission".format(name, link_target))
