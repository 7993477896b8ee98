"""The two commands' arguments, read as the C++ originals read them (no ROS import).

Numbers go through C's atoi/atof rules, as the originals' do: the longest numeric prefix counts and anything else
is 0, so `--free abc` means 0 and `map_server map.pgm abc` (resolution 0) reads map.pgm as a YAML. ROS remapping
arguments (name:=value) are removed before these functions see the list.
"""

import re
from dataclasses import dataclass

from lab_nav.maps.map_saver_files import DEFAULT_FREE_THRESHOLD, DEFAULT_OCCUPIED_THRESHOLD

SERVER_USAGE = ("\nUSAGE: map_server <map.yaml>\n"
                "  map.yaml: map description file\n"
                "DEPRECATED USAGE: map_server <map> <resolution>\n"
                "  map: image file to load\n"
                "  resolution: map resolution [meters/pixel]")
SERVER_DEPRECATED_WARNING = "Using deprecated map server interface. Please switch to new interface."
SAVER_USAGE = ("Usage: \n"
               "  map_saver -h\n"
               "  map_saver [--occ <threshold_occupied>] [--free <threshold_free>] [-f <mapname>] "
               "[ROS remapping args]")
OCCUPIED_RANGE = (1, 100)
FREE_RANGE = (0, 100)
EXIT_USAGE_ERROR = 1
EXIT_SERVER_ERROR = 255   # the original's exit(-1)

_ATOI = re.compile(r"\s*[+-]?\d+")
_ATOF = re.compile(r"\s*[+-]?(\d+\.?\d*([eE][+-]?\d+)?|\.\d+([eE][+-]?\d+)?|inf(inity)?|nan)", re.IGNORECASE)


def c_atoi(text):
    """C's atoi: the integer at the start of `text` (after blanks), or 0."""
    match = _ATOI.match(text)
    return int(match.group()) if match else 0


def c_atof(text):
    """C's atof: the number at the start of `text` (after blanks), or 0.0."""
    match = _ATOF.match(text)
    return float(match.group()) if match else 0.0


class CommandLineExit(Exception):
    """The command ends before it starts: `code` is its exit code, `output` what it prints on stdout (usage), and
    `error` the ERROR line it logs (or None)."""

    def __init__(self, code, output=None, error=None):
        super().__init__(error or output)
        self.code, self.output, self.error = code, output, error


@dataclass(frozen=True)
class SaverOptions:
    """map_saver's options: the file name without extension and the two integer thresholds (percent)."""

    name: str = "map"
    occupied: int = DEFAULT_OCCUPIED_THRESHOLD
    free: int = DEFAULT_FREE_THRESHOLD


def _threshold(value, name, allowed):
    number = c_atoi(value)
    if not allowed[0] <= number <= allowed[1]:
        raise CommandLineExit(EXIT_USAGE_ERROR, error="{} must be between {} and {}".format(name, *allowed))
    return number


def parse_saver_args(args):
    """SaverOptions from map_saver's arguments, read left to right as the original does; raises CommandLineExit:
    -h -> usage, exit 0; an unknown argument or a missing value -> usage, exit 1; a threshold out of range or
    free >= occupied -> its ERROR line, exit 1."""
    values = {"-f": "map", "--occ": str(DEFAULT_OCCUPIED_THRESHOLD), "--free": str(DEFAULT_FREE_THRESHOLD)}
    checks = {"--occ": ("threshold_occupied", OCCUPIED_RANGE), "--free": ("threshold_free", FREE_RANGE)}
    position = 0
    while position < len(args):
        flag = args[position]
        if flag == "-h":
            raise CommandLineExit(0, output=SAVER_USAGE)
        if flag not in values or position + 1 >= len(args):
            raise CommandLineExit(EXIT_USAGE_ERROR, output=SAVER_USAGE)
        values[flag] = args[position + 1]
        if flag in checks:
            _threshold(values[flag], *checks[flag])
        position += 2
    occupied, free = c_atoi(values["--occ"]), c_atoi(values["--free"])
    if occupied <= free:
        raise CommandLineExit(EXIT_USAGE_ERROR, error="threshold_free must be smaller than threshold_occupied")
    return SaverOptions(name=values["-f"], occupied=occupied, free=free)


@dataclass(frozen=True)
class ServerArgs:
    """map_server's arguments: the YAML path, or (deprecated form) an image path with a non-zero resolution."""

    path: str
    resolution: float = 0.0

    @property
    def deprecated(self):
        return self.resolution != 0


def parse_server_args(args):
    """ServerArgs from map_server's arguments; raises CommandLineExit (usage as an ERROR, exit 255) unless there
    are one or two. With two, the second is the resolution through atof, and a resolution of 0 means the first is
    read as a YAML after all, as in the original."""
    if len(args) not in (1, 2):
        raise CommandLineExit(EXIT_SERVER_ERROR, error=SERVER_USAGE)
    return ServerArgs(args[0], c_atof(args[1]) if len(args) == 2 else 0.0)
