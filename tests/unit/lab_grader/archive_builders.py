"""Builders of submission folders and archives (well-formed and hostile) for the lab_grader unit tests."""
import io
import stat
import tarfile
import zipfile
from pathlib import Path

PACKAGE_XML = """<?xml version="1.0"?>
<package format="3">
  <name>{}</name>
  <version>0.0.1</version>
  <description>a student's package</description>
  <maintainer email="student@example.org">student</maintainer>
  <license>BSD</license>
  <buildtool_depend>catkin</buildtool_depend>
</package>
"""


def package_files(name, prefix=""):
    """{relative path: content} of a minimal catkin package called `name`, under `prefix`."""
    return {prefix + "package.xml": PACKAGE_XML.format(name),
            prefix + "CMakeLists.txt": "cmake_minimum_required(VERSION 3.0.2)\nproject({})\n".format(name),
            prefix + "scripts/node.py": "#!/usr/bin/env python3\nprint('hello')\n"}


def write_folder(folder: Path, files: dict) -> Path:
    for relative, content in files.items():
        path = folder / relative
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(content)
    return folder


def make_zip(path: Path, files: dict, symlinks: dict = None, modes: dict = None) -> Path:
    """A zip of `files` ({name: text}), `symlinks` ({name: target}) and Unix `modes` ({name: mode bits})."""
    with zipfile.ZipFile(path, "w", zipfile.ZIP_DEFLATED) as zf:
        for name, content in files.items():
            info = zipfile.ZipInfo(name)
            info.external_attr = (stat.S_IFREG | (modes or {}).get(name, 0o644)) << 16
            info.compress_type = zipfile.ZIP_DEFLATED
            zf.writestr(info, content)
        for name, target in (symlinks or {}).items():
            info = zipfile.ZipInfo(name)
            info.external_attr = (stat.S_IFLNK | 0o777) << 16
            zf.writestr(info, target)
    return path


def tar_file(name, content, mode=0o644):
    data = content.encode() if isinstance(content, str) else content
    info = tarfile.TarInfo(name)
    info.size = len(data)
    info.mode = mode
    return info, io.BytesIO(data)


def tar_entry(name, kind, linkname=""):
    """A tar member without content: kind is one of tarfile's types (SYMTYPE, LNKTYPE, CHRTYPE, FIFOTYPE, ...)."""
    info = tarfile.TarInfo(name)
    info.type = kind
    info.linkname = linkname
    if kind == tarfile.DIRTYPE:
        info.mode = 0o755
    return info, None


def make_tar(path: Path, members: list) -> Path:
    """A .tar.gz / .tgz of (TarInfo, content or None) pairs, in order."""
    with tarfile.open(path, "w:gz") as tar:
        for info, content in members:
            tar.addfile(info, content)
    return path
