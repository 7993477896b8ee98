"""The images a student's action server says it saved: find the folder its result names, count and decode them
(plain Python; OpenCV is imported only when an image is decoded).

The CameraSweep result's image_path names a folder the way the course prints it, "~/myrosdata/action_examples/
<stamp>", where "~" is the student's HOME (in the grader's sandbox, the submission's workspace; run_checks
--student-home). A path after a space and "[" is a note (the reference's "<folder> [PRE-EMPTED at image 2 of 4]").

The folder and the files are the student's, so they are read as untrusted: the folder must resolve inside the
student's home (no "..", no link out), links are not followed, at most MAX_FILES files are looked at and at most
MAX_IMAGE_BYTES read of each; an image "decodes" when OpenCV makes a non-empty picture of its bytes.
"""
import os
from pathlib import Path
from typing import Callable, NamedTuple, Optional, Tuple

IMAGE_SUFFIXES = (".jpg", ".jpeg", ".png")
MAX_FILES = 200
MAX_IMAGE_BYTES = 20 * 2 ** 20


class ImageFolder(NamedTuple):
    """What was found: the folder as the result named it, the image files in it (names, sorted), those that decode,
    and a problem (None when the folder could be read)."""

    named: str
    images: Tuple[str, ...] = ()
    decodable: Tuple[str, ...] = ()
    problem: Optional[str] = None


def decode(data: bytes) -> bool:
    """Whether OpenCV makes a non-empty image of `data`."""
    import cv2
    import numpy
    image = cv2.imdecode(numpy.frombuffer(data, numpy.uint8), cv2.IMREAD_UNCHANGED)
    return image is not None and image.size > 0


def folder_in_home(named: str, home: Path) -> Path:
    """The folder `named` ("~/a/b", "/abs", or relative to home) names, inside `home`; ValueError if it is not."""
    text = named.split(" [")[0].strip()
    if not text:
        raise ValueError("the result names no folder")
    if text == "~" or text.startswith("~/"):
        text = text[2:]
    home = Path(os.path.realpath(home))
    folder = Path(os.path.realpath(home / text))
    if folder != home and home not in folder.parents:
        raise ValueError("{} is outside the student's home folder".format(text))
    return folder


def inspect(named, home, decoder: Callable[[bytes], bool] = decode) -> ImageFolder:
    """The ImageFolder for the result text `named`, the student's home being `home` (None: unknown)."""
    if not isinstance(named, str):
        return ImageFolder(str(named), problem="the result has no image folder path")
    if home is None:
        return ImageFolder(named, problem="the student's home folder is not known (run_checks --student-home)")
    try:
        folder = folder_in_home(named, home)
        entries = sorted(os.scandir(folder), key=lambda entry: entry.name)[:MAX_FILES]
    except ValueError as error:
        return ImageFolder(named, problem=str(error))
    except OSError as error:
        return ImageFolder(named, problem="cannot read the folder: {}".format(error.strerror or error))
    images = [entry for entry in entries if entry.name.lower().endswith(IMAGE_SUFFIXES)
              and entry.is_file(follow_symlinks=False)]
    decodable = []
    for entry in images:
        try:
            with open(entry.path, "rb", opener=lambda path, flags: os.open(path, flags | os.O_NOFOLLOW)) as file:
                data = file.read(MAX_IMAGE_BYTES + 1)
        except OSError:
            continue
        if len(data) <= MAX_IMAGE_BYTES and decoder(data):
            decodable.append(entry.name)
    return ImageFolder(named, tuple(entry.name for entry in images), tuple(decodable))
