"""Where a camera sweep saves its images and what the result's image_path says (plain Python, no rospy).

As the COM2009 template: one folder per sweep, ~/myrosdata/action_examples/<YYYYMMDD_HHMMSS>/ (the local
wall-clock time the sweep started: the folder is for people to find; all robot timing is rospy time), images
img001.jpg, img002.jpg, ... in capture order, and image_path written with "~" for the home folder. A second
sweep started in the same second gets a folder with "_2" (then "_3", ...) appended instead of overwriting the
first one's images.

image_path of the result:
- succeeded: the folder, e.g. "~/myrosdata/action_examples/20250101_120000"
- preempted: the folder and how far it got, "~/myrosdata/... [PRE-EMPTED at image 2 of 4]"
- aborted:   "None [ABORTED: <reason>]", the course's "None [ABORTED]" with the reason (also the goal status
             text and the log line); a sweep that fails midway adds where its images so far are.
"""
from pathlib import Path

FOLDER_UNDER_HOME = Path("myrosdata", "action_examples")
TIMESTAMP_FORMAT = "%Y%m%d_%H%M%S"
MAX_SAME_SECOND_FOLDERS = 100


def new_sweep_folder(home, started):
    """Create and return the folder for a sweep started at datetime `started` (see the module docstring);
    OSError if it cannot be created."""
    base = Path(home) / FOLDER_UNDER_HOME / started.strftime(TIMESTAMP_FORMAT)
    for number in range(1, MAX_SAME_SECOND_FOLDERS + 1):
        folder = base if number == 1 else base.with_name("{}_{}".format(base.name, number))
        try:
            folder.mkdir(parents=True)
            return folder
        except FileExistsError:
            continue
    raise FileExistsError("{} sweep folders for {} already exist".format(MAX_SAME_SECOND_FOLDERS, base))


def image_file_name(number):
    """The file name of the `number`-th image of a sweep (1-based): img001.jpg, img002.jpg, ..."""
    return "img{:03d}.jpg".format(number)


def display_path(path, home):
    """`path` as text, with `home` written "~" when the path is inside it (as the course prints it)."""
    path, home = Path(path), Path(home)
    try:
        return str(Path("~") / path.relative_to(home))
    except ValueError:
        return str(path)


def preempted_text(folder_text, captured, count):
    return "{} [PRE-EMPTED at image {} of {}]".format(folder_text, captured, count)


def aborted_text(reason, folder_text=None, captured=0):
    """The aborted image_path; with the folder when images were already saved there."""
    saved = "" if not folder_text or not captured else " ({} image{} saved in {})".format(
        captured, "" if captured == 1 else "s", folder_text)
    return "None [ABORTED: {}{}]".format(reason, saved)
