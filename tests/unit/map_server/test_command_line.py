"""map_saver's and map_server's arguments, read as the C++ originals read them."""
import pytest

from map_server.command_line import (
    SAVER_USAGE,
    SERVER_USAGE,
    CommandLineExit,
    SaverOptions,
    c_atof,
    c_atoi,
    parse_saver_args,
    parse_server_args,
)


def stop_of(parse, args):
    with pytest.raises(CommandLineExit) as stop:
        parse(args)
    return stop.value


def test_map_saver_defaults_and_every_option():
    assert parse_saver_args([]) == SaverOptions("map", 65, 25)
    assert parse_saver_args(["--free", "10", "-f", "maps/room", "--occ", "90"]) == SaverOptions("maps/room", 90, 10)


def test_help_prints_the_usage_and_exits_0():
    stop = stop_of(parse_saver_args, ["-f", "x", "-h"])
    assert (stop.code, stop.output, stop.error) == (0, SAVER_USAGE, None)
    assert SAVER_USAGE.startswith("Usage: \n  map_saver -h\n")


@pytest.mark.parametrize("args", [["--file", "x"], ["-f"], ["--occ"], ["x"]])
def test_an_unknown_argument_or_a_missing_value_prints_the_usage_and_exits_1(args):
    stop = stop_of(parse_saver_args, args)
    assert (stop.code, stop.output, stop.error) == (1, SAVER_USAGE, None)


@pytest.mark.parametrize("args, error", [
    (["--occ", "0"], "threshold_occupied must be between 1 and 100"),
    (["--occ", "101"], "threshold_occupied must be between 1 and 100"),
    (["--free", "-1"], "threshold_free must be between 0 and 100"),
    (["--occ", "20"], "threshold_free must be smaller than threshold_occupied"),
    (["--free", "65"], "threshold_free must be smaller than threshold_occupied"),
    (["--occ", "0", "-h"], "threshold_occupied must be between 1 and 100"),   # checked as it is read
])
def test_a_bad_threshold_logs_its_error_and_exits_1(args, error):
    stop = stop_of(parse_saver_args, args)
    assert (stop.code, stop.output, stop.error) == (1, None, error)


def test_thresholds_are_read_with_atoi():
    assert parse_saver_args(["--free", "abc", "--occ", "70%"]) == SaverOptions("map", 70, 0)
    assert (c_atoi(" -12x"), c_atoi("x12"), c_atof("0.05m"), c_atof("5e-2"), c_atof("abc")) == (
        -12, 0, 0.05, 0.05, 0.0)


def test_map_server_takes_a_yaml_or_the_deprecated_image_and_resolution():
    assert not parse_server_args(["room.yaml"]).deprecated
    args = parse_server_args(["room.pgm", "0.05"])
    assert (args.path, args.resolution, args.deprecated) == ("room.pgm", 0.05, True)
    assert not parse_server_args(["room.pgm", "fine"]).deprecated   # atof gives 0: read as a YAML


@pytest.mark.parametrize("args", [[], ["a", "b", "c"]])
def test_map_server_with_another_count_logs_the_usage_and_exits_255(args):
    stop = stop_of(parse_server_args, args)
    assert (stop.code, stop.error) == (255, SERVER_USAGE)
    assert SERVER_USAGE.startswith("\nUSAGE: map_server <map.yaml>\n")
