"""window_hint without ROS: the X display probe, the hint line, the relay's table and decisions, and the course
commands' argument translations (rqt_image_view) and graph (rqt_graph)."""
import socket
import subprocess
import sys

import pytest
from rqt_graph.dot_graph import node_graph, to_dot
from rqt_image_view.main import image_view_args
from window_hint.display import X11_TCP_BASE_PORT, display_problem, display_reachable, x_server_address
from window_hint.hints import WINDOWS, can_open_window, no_display_line
from window_hint.relay import command_text, load_redirects, ros_name, run


@pytest.mark.parametrize("display, expected", [
    (":0", [(socket.AF_UNIX, "\0/tmp/.X11-unix/X0"), (socket.AF_UNIX, "/tmp/.X11-unix/X0")]),
    ("unix:12.0", [(socket.AF_UNIX, "\0/tmp/.X11-unix/X12"),
                   (socket.AF_UNIX, "/tmp/.X11-unix/X12")]),
    ("localhost:10.0", [(socket.AF_INET, ("localhost", X11_TCP_BASE_PORT + 10))]),
    ("", []), ("nonsense", []), (None, []),
])
def test_x_server_addresses(display, expected):
    assert x_server_address(display) == expected


def test_a_display_nobody_listens_on_is_unreachable():
    assert not display_reachable(":98765")
    assert not display_reachable("garbage")


def test_a_listening_x_socket_is_reachable(monkeypatch, tmp_path):
    path = str(tmp_path / "X7")
    monkeypatch.setattr("window_hint.display.X11_SOCKET", str(tmp_path / "X%d"))
    with socket.socket(socket.AF_UNIX, socket.SOCK_STREAM) as server:
        server.bind(path)
        server.listen(1)
        assert display_reachable(":7")


def test_a_wayland_session_or_an_answering_x_server_is_a_display(monkeypatch, tmp_path):
    assert display_problem({"WAYLAND_DISPLAY": "wayland-0"}) is None
    assert display_problem({}) == "no display"
    assert display_problem({"DISPLAY": ":98765"}) == "no display (the X server at DISPLAY=:98765 does not answer)"
    monkeypatch.setattr("window_hint.display.X11_SOCKET", str(tmp_path / "X%d"))
    with socket.socket(socket.AF_UNIX, socket.SOCK_STREAM) as server:
        server.bind(str(tmp_path / "X3"))
        server.listen(1)
        assert display_problem({"DISPLAY": ":3"}) is None


@pytest.mark.parametrize("tool", sorted(WINDOWS))
def test_each_window_has_one_line_naming_where_to_see_it_and_xvfb_run(tool):
    line = no_display_line(tool, command=f"rosrun x {tool}")
    assert "\n" not in line and line.startswith(f"[{tool}] no display, so ")
    assert line.endswith(f"xvfb-run -a rosrun x {tool}")
    assert "See it here: " in line


def test_the_line_says_what_was_done_instead():
    line = no_display_line("rqt_graph", instead="the graph is written to /tmp/rosgraph.png")
    assert "is not started; the graph is written to /tmp/rosgraph.png. See it here: roslaunch lab_web" in line


def test_every_relayed_tool_names_an_installed_debian_program_and_a_hint():
    redirects = load_redirects()
    assert set(redirects) == {"rviz/rviz", "image_view/image_view", "actionlib/axclient.py", "actionlib/axserver.py",
                              "actionlib_tools/axclient.py", "actionlib_tools/axserver.py"}
    for redirect in redirects.values():
        assert redirect.hint in WINDOWS
        assert subprocess.run(["test", "-x", redirect.program]).returncode == 0, redirect.program


def test_the_relay_knows_its_tool_by_the_path_it_was_started_as():
    assert ros_name("/ws/devel/lib/actionlib/axclient.py") == "actionlib/axclient.py"
    assert command_text("rviz/rviz", ["-d", "a.rviz", "__name:=rviz", "__log:=/x.log"]) == "rosrun rviz rviz -d a.rviz"


def test_without_a_display_the_relay_prints_the_line_and_does_not_start_the_program(capsys):
    assert run("/bin/false", ["-d", "x"], "rviz", "rosrun rviz rviz", environ={}) == 0
    assert capsys.readouterr().err == no_display_line("rviz", "no display", "rosrun rviz rviz") + "\n"


def test_with_a_display_the_relay_becomes_the_program(tmp_path):
    """The relay in a child process with WAYLAND_DISPLAY set execs the program with the arguments."""
    script = f'echo "$0 $1" > {tmp_path}/ran'
    code = ("from window_hint.relay import run; "
            f"run('/bin/sh', ['-c', {script!r}, 'a', 'b'], 'rviz', 'x', {{'WAYLAND_DISPLAY': 'w'}})")
    subprocess.run([sys.executable, "-c", code], check=True, timeout=30)
    assert (tmp_path / "ran").read_text() == "a b\n"


@pytest.mark.parametrize("args, expected", [
    ([], ["image:=/camera/rgb/image_raw"]),
    (["/camera/rgb/image_raw"], ["image:=/camera/rgb/image_raw"]),
    (["/camera/rgb/image_raw/compressed"], ["image:=/camera/rgb/image_raw", "_image_transport:=compressed"]),
    (["/cam/theora", "__ns:=/r1"], ["image:=/cam", "_image_transport:=theora", "__ns:=/r1"]),
])
def test_rqt_image_view_arguments_become_image_views(args, expected):
    assert image_view_args(args) == expected


def test_rqt_graph_draws_node_to_node_arrows_labelled_with_topics_and_hides_rosout():
    publishers = [["/chatter", ["/talker"]], ["/rosout", ["/talker", "/listener"]], ["/rosout_agg", ["/rosout"]],
                  ["/unheard", ["/talker"]]]
    subscribers = [["/chatter", ["/listener", "/listener2"]], ["/rosout", ["/rosout"]], ["/tf", ["/lonely"]]]
    graph = node_graph(publishers, subscribers)
    assert graph.nodes == ["/listener", "/listener2", "/lonely", "/talker"]
    assert graph.edges == [("/talker", "/listener", "/chatter"), ("/talker", "/listener2", "/chatter")]
    dot = to_dot(graph)
    assert '"/talker" -> "/listener" [label="/chatter"];' in dot and "rosout" not in dot
    rendered = subprocess.run(["dot", "-Tsvg"], input=dot, stdout=subprocess.PIPE, text=True, check=True)
    assert "/listener2" in rendered.stdout


def test_a_node_logs_the_line_as_info_without_a_display_and_as_a_warning_for_a_silent_x_server():
    said = []
    info, warn = (lambda text: said.append(("info", text))), (lambda text: said.append(("warn", text)))
    assert not can_open_window("turtlesim", "rosrun turtlesim turtlesim_node", info, warn, environ={})
    assert not can_open_window("turtlesim", "x", info, warn, environ={"DISPLAY": ":98765"})
    assert can_open_window("turtlesim", "x", info, warn, environ={"WAYLAND_DISPLAY": "wayland-0"})
    assert [level for level, _ in said] == ["info", "warn"]
    assert said[0][1] == no_display_line("turtlesim", "no display", "rosrun turtlesim turtlesim_node")
