"""`rosrun map_server map_server MAP.yaml` and `rosrun map_server map_saver -f NAME` on one real master: latched
topics and their content, /static_map, /change_map, ~frame_id, the errors a user sees, map_saver's files byte for
byte (from the shell, a subprocess `cd DIR && rosrun ...`, and the roslaunch Python API as course code calls it),
map:= remapping, the round trip, sim time, and a student's node reading /map with numpy."""
import json
import re
import sys

import numpy as np
import pytest
import rosgraph
import rospy
from nav_msgs.srv import GetMap, LoadMap
from PIL import Image

from roslab.map_reading import read_map_as_a_student
from roslab.waiting import service_uri, wait_for_service, wait_for_topic, wait_until

START_S = 90   # hang guard for a node to start and publish (a loaded machine has taken 30 s to start one)

# room.pgm, top image row first, and the cells map_server makes of it (row 0 = the image's bottom row)
ROOM_PIXELS = [[0, 254, 205, 254],
               [254, 0, 0, 205],
               [254, 254, 254, 0]]
ROOM_CELLS = [[0, 0, 0, 100],
              [0, 100, 100, -1],
              [100, 0, -1, 0]]
ROOM_YAML = ("image: room.pgm\nresolution: 0.05\norigin: [-1.0, 2.5, 0.0]\nnegate: 0\n"
             "occupied_thresh: 0.65\nfree_thresh: 0.196\n")
# corridor.png in raw mode with a yaw: the values themselves, 200 wrapping to -56
CORRIDOR_YAML = ("image: corridor.png\nresolution: 0.1\norigin: [0.5, 0.0, 1.0]\nnegate: 0\n"
                 "occupied_thresh: 0.65\nfree_thresh: 0.196\nmode: raw\n")
CORRIDOR_CELLS = [[10, -56]]

# the grid the test publishes for map_saver: 2 rows x 4 columns covering both thresholds
SAVED_CELLS = [[0, 25, 26, 64],
               [65, 100, -1, 50]]
SAVED_PGM = (b"P5\n# CREATOR: map_saver.cpp 0.050 m/pix\n4 2\n255\n"
             + bytes([0, 0, 205, 205])        # map row 1 on top
             + bytes([254, 254, 205, 205]))   # map row 0
SAVED_YAML = ("image: {}.pgm\nresolution: 0.050000\norigin: [-1.500000, 2.250000, -0.300000]\nnegate: 0\n"
              "occupied_thresh: 0.65\nfree_thresh: 0.196\n\n")
SAVER_LINES = ["Waiting for the map", "Received a 4 X 2 map @ 0.050 m/pix",
               "Writing map occupancy data to {0}.pgm", "Writing map occupancy data to {0}.yaml", "Done"]

ROSLAUNCH_API_SAVER = """
import sys
import time
import roslaunch

launch = roslaunch.scriptapi.ROSLaunch()
launch.start()
for _ in range(2):   # course code saves the map again and again to the same path
    process = launch.launch(roslaunch.core.Node("map_server", "map_saver", args="-f " + sys.argv[1]))
    while process.is_alive():
        time.sleep(0.1)
    print("SAVED", process.name, process.exit_code)
launch.stop()
"""


@pytest.fixture(scope="module")
def maps(tmp_path_factory):
    folder = tmp_path_factory.mktemp("maps")
    Image.fromarray(np.array(ROOM_PIXELS, np.uint8)).save(folder / "room.pgm")
    (folder / "room.yaml").write_text(ROOM_YAML)
    Image.fromarray(np.array([[10, 200]], np.uint8)).save(folder / "corridor.png")
    (folder / "corridor.yaml").write_text(CORRIDOR_YAML)
    return folder


@pytest.fixture(scope="module")
def probe(ros_master):
    probe = ros_master.probe()
    probe.subscribe("/map", "nav_msgs/OccupancyGrid", wait_s=0.0)
    probe.subscribe("/map_metadata", "nav_msgs/MapMetaData", wait_s=0.0)
    return probe


def node_names(ros_master):
    publishers, subscribers, services = rosgraph.Master("/test", master_uri=ros_master.uri).getSystemState()
    return {node for _, nodes in publishers + subscribers + services for node in nodes}


def cells(grid_msg):
    return np.array(grid_msg["data"]).reshape(grid_msg["info"]["height"], grid_msg["info"]["width"]).tolist()


def finished(process, timeout_s=120):
    """The exit code of a process that is expected to end by itself (the limit only catches a hang: a loaded
    machine has taken 30 s for one `rosrun map_server map_saver`)."""
    return process.popen.wait(timeout=timeout_s)


def fresh(probe):
    """The probe with the /map and /map_metadata messages of earlier tests dropped."""
    probe.take("/map")
    probe.take("/map_metadata")
    return probe


def start_map_server(ros_master, *args):
    return ros_master.rosrun("map_server", "map_server", *args)


def grid_yaml(cells, resolution=0.05, origin=(-1.5, 2.25), yaw=-0.3):
    """A nav_msgs/OccupancyGrid as the YAML `rostopic pub` takes."""
    rows = np.array(cells)
    return json.dumps({"header": {"frame_id": "map"},
                       "info": {"resolution": resolution, "width": int(rows.shape[1]), "height": int(rows.shape[0]),
                                "origin": {"position": {"x": origin[0], "y": origin[1], "z": 0.0},
                                           "orientation": {"z": float(np.sin(yaw / 2)), "w": float(np.cos(yaw / 2))}}},
                       "data": rows.ravel().tolist()})


def latched_grid(ros_master, topic, cells, **geometry):
    """`rostopic pub TOPIC nav_msgs/OccupancyGrid ...` without a rate: it publishes once, latched, and stays."""
    process = ros_master.start(["rostopic", "pub", topic, "nav_msgs/OccupancyGrid", grid_yaml(cells, **geometry)],
                               "rostopic_pub")
    wait_for_topic(ros_master.uri, topic)
    return process


def info_lines(output):
    """The INFO lines' texts; the lines are in roscpp's format, as the C++ originals print them."""
    return [match.group(1) for match in re.finditer(r"^\[ INFO\] \[\d+\.\d{9}\]: (.*)$", output, re.MULTILINE)]


def test_rosrun_map_server_serves_the_yaml_latched_once_on_an_anonymous_node(ros_master, maps, probe):
    server = ros_master.start(["rosrun", "map_server", "map_server", str(maps / "room.yaml")], "rosrun_map_server")
    try:
        grid = fresh(probe).wait_for_message("/map", timeout_s=START_S)
        metadata = probe.wait_for_message("/map_metadata")
        assert cells(grid) == ROOM_CELLS
        assert grid["header"]["frame_id"] == "map"
        assert grid["info"] == metadata
        assert (metadata["width"], metadata["height"]) == (4, 3)
        assert metadata["resolution"] == pytest.approx(0.05)
        assert (metadata["origin"]["position"]["x"], metadata["origin"]["position"]["y"]) == (-1.0, 2.5)
        assert metadata["origin"]["orientation"]["w"] == 1.0
        assert grid["header"]["stamp"] == metadata["map_load_time"]
        assert [name for name in node_names(ros_master) if re.fullmatch(r"/map_server_\d{18,}", name)]
        assert probe.collect("/map", 1.0) == []   # published once: nothing more arrives
        output = server.output()
        assert 'Loading map from image "{}"'.format(maps / "room.pgm") in output
        assert "Read a 4 X 3 map @ 0.050 m/cell" in output
    finally:
        server.stop()


def test_static_map_and_change_map_answer_and_republish(ros_master, maps, probe):
    fresh(probe)
    server = start_map_server(ros_master, str(maps / "room.yaml"))
    try:
        wait_for_service(ros_master.uri, "/change_map")
        probe.wait_for_message("/map", timeout_s=START_S)
        reply = rospy.ServiceProxy("/static_map", GetMap)()
        assert np.array(reply.map.data).reshape(3, 4).tolist() == ROOM_CELLS
        wait_until(lambda: "Sending map" in server.output(), 10, "the Sending map line")

        change = rospy.ServiceProxy("/change_map", LoadMap)
        reply = change(str(maps / "corridor.yaml"))
        assert (reply.result, list(reply.map.data)) == (0, CORRIDOR_CELLS[0])
        grid = probe.wait_for_message("/map")
        assert cells(grid) == CORRIDOR_CELLS
        assert grid["info"]["origin"]["orientation"]["z"] == pytest.approx(np.sin(0.5))
        assert list(rospy.ServiceProxy("/static_map", GetMap)().map.data) == CORRIDOR_CELLS[0]
        assert "Changed map to {}".format(maps / "corridor.yaml") in server.output()

        assert change(str(maps / "missing.yaml")).result == 255
        wait_until(lambda: "Map_server could not open {}.".format(maps / "missing.yaml") in server.output(), 10,
                   "the change_map error line")
        assert server.running()
        assert list(rospy.ServiceProxy("/static_map", GetMap)().map.data) == CORRIDOR_CELLS[0]
    finally:
        server.stop()


def test_a_launch_name_and_frame_id_are_used(ros_master, maps, probe):
    server = start_map_server(ros_master, str(maps / "room.yaml"), "__name:=map_server", "_frame_id:=world")
    try:
        assert fresh(probe).wait_for_message("/map", timeout_s=START_S)["header"]["frame_id"] == "world"
        assert "/map_server" in node_names(ros_master)
    finally:
        server.stop()


def test_the_deprecated_image_and_resolution_form_warns_and_uses_origin_zero(ros_master, maps, probe):
    server = start_map_server(ros_master, str(maps / "room.pgm"), "0.1", "_negate:=1")
    try:
        grid = fresh(probe).wait_for_message("/map", timeout_s=START_S)
        # negated: white 254 reads as 1 (occupied), black as 255 (free), and grey 205 as 50, which is occupied too
        assert cells(grid) == [[{0: 100, 100: 0, -1: 100}[cell] for cell in row] for row in ROOM_CELLS]
        assert (grid["info"]["resolution"], grid["info"]["origin"]["position"]["x"]) == (pytest.approx(0.1), 0.0)
        assert "[ WARN]" in server.output()
        assert "Using deprecated map server interface. Please switch to new interface." in server.output()
    finally:
        server.stop()


@pytest.mark.parametrize("yaml_text, args, message", [
    (None, ["missing.yaml"], "Map_server could not open {folder}/missing.yaml."),
    (ROOM_YAML.replace("resolution: 0.05\n", ""), ["bad.yaml"],
     "The map does not contain a resolution tag or it is invalid."),
    (ROOM_YAML + "mode: grey\n", ["bad.yaml"], 'Invalid mode tag "grey".'),
    (ROOM_YAML.replace("room.pgm", "nothing.pgm"), ["bad.yaml"],
     'failed to open image file "{folder}/nothing.pgm": No such file or directory'),
    (None, [], "USAGE: map_server <map.yaml>"),
])
def test_errors_are_the_originals_lines_with_exit_code_255(ros_master, maps, tmp_path, yaml_text, args, message):
    if yaml_text is not None:
        (tmp_path / "bad.yaml").write_text(yaml_text)
        (tmp_path / "room.pgm").write_bytes((maps / "room.pgm").read_bytes())
    server = start_map_server(ros_master, *[str(tmp_path / arg) for arg in args])
    assert finished(server) == 255
    output = server.output()
    assert "[ERROR]" in output and message.format(folder=tmp_path) in output
    assert "Traceback" not in output


def run_saver(ros_master, folder, *args):
    """`cd FOLDER && rosrun map_server map_saver ARGS`, as a shell (or course code's subprocess) runs it."""
    command = "cd {} && rosrun map_server map_saver {}".format(folder, " ".join(args))
    return ros_master.start(["bash", "-c", command], "map_saver")


def test_map_saver_writes_the_latched_map_byte_for_byte_and_exits_0(ros_master, tmp_path):
    publisher = latched_grid(ros_master, "/map", SAVED_CELLS)
    try:
        (tmp_path / "maps").mkdir()
        saver = run_saver(ros_master, tmp_path, "-f", "maps/lab")
        assert finished(saver) == 0
        assert (tmp_path / "maps" / "lab.pgm").read_bytes() == SAVED_PGM
        assert (tmp_path / "maps" / "lab.yaml").read_text() == SAVED_YAML.format("maps/lab")
        output = saver.output()
        assert info_lines(output) == [line.format("maps/lab") for line in SAVER_LINES]
        assert "Done\n\n" in output

        saver = run_saver(ros_master, tmp_path, "--occ", "50", "--free", "0")
        assert finished(saver) == 0
        assert (tmp_path / "map.pgm").read_bytes()[-8:] == bytes([0, 0, 205, 0, 254, 205, 205, 0])
        assert (tmp_path / "map.yaml").read_text() == SAVED_YAML.format("map")   # thresholds stay 0.65 / 0.196
    finally:
        publisher.stop()


def test_map_saver_follows_a_remapped_topic(ros_master, tmp_path):
    publisher = latched_grid(ros_master, "/other_map", [[100, 0]], resolution=0.1, origin=(0.0, 0.0), yaw=0.0)
    try:
        saver = ros_master.rosrun("map_server", "map_saver", "-f", str(tmp_path / "other"), "map:=/other_map")
        assert finished(saver) == 0
        assert (tmp_path / "other.pgm").read_bytes() == b"P5\n# CREATOR: map_saver.cpp 0.100 m/pix\n2 1\n255\n\x00\xfe"
        assert "origin: [0.000000, 0.000000, 0.000000]" in (tmp_path / "other.yaml").read_text()
    finally:
        publisher.stop()


def test_map_saver_that_cannot_write_says_so_and_keeps_waiting(ros_master, tmp_path):
    publisher = latched_grid(ros_master, "/map", SAVED_CELLS)
    saver = ros_master.rosrun("map_server", "map_saver", "-f", str(tmp_path / "no_such_folder" / "map"))
    try:
        wait_until(lambda: "Couldn't save map file to {}".format(tmp_path / "no_such_folder" / "map.pgm")
                   in saver.output(), START_S, "the write error")
        assert saver.running()
    finally:
        saver.stop()
        publisher.stop()


@pytest.mark.parametrize("args, code, text", [
    (["-h"], 0, "Usage: \n  map_saver -h\n"),
    (["--file", "x"], 1, "Usage: \n  map_saver -h\n"),
    (["--occ", "101"], 1, "[ERROR]"),
    (["--occ", "20", "--free", "30"], 1, "threshold_free must be smaller than threshold_occupied"),
])
def test_map_saver_usage_and_threshold_errors(ros_master, args, code, text):
    saver = ros_master.rosrun("map_server", "map_saver", *args)
    assert finished(saver) == code
    assert text in saver.output()
    assert "Waiting for the map" not in saver.output()


def test_course_code_saves_with_the_roslaunch_api_under_an_anonymous_name(ros_master, tmp_path):
    publisher = latched_grid(ros_master, "/map", SAVED_CELLS)
    try:
        target = tmp_path / "arena"
        script = ros_master.start([sys.executable, "-c", ROSLAUNCH_API_SAVER, str(target)], "roslaunch_api")
        assert finished(script, timeout_s=180) == 0
        runs = re.findall(r"^SAVED (\S+) (\S+)$", script.output(), re.MULTILINE)
        assert [code for _, code in runs] == ["0", "0"]
        assert all(re.fullmatch(r"map_saver_\w+_\d+_\d+-\d+", name) for name, _ in runs), runs   # anonymous
        assert (tmp_path / "arena.pgm").read_bytes() == SAVED_PGM
        assert (tmp_path / "arena.yaml").read_text() == SAVED_YAML.format(target)
    finally:
        publisher.stop()


def test_a_saved_map_loads_back_as_the_same_grid_and_a_student_node_reads_it(ros_master, tmp_path, probe):
    slam_like = [[-1, -1, 0, 0, 100], [-1, 0, 0, 100, 100], [0, 0, 0, 0, 100]]
    publisher = latched_grid(ros_master, "/map", slam_like, origin=(-2.0, -3.0), yaw=0.0)
    try:
        assert finished(ros_master.rosrun("map_server", "map_saver", "-f", str(tmp_path / "saved"))) == 0
    finally:
        publisher.stop()
    server = start_map_server(ros_master, str(tmp_path / "saved.yaml"))
    try:
        grid = fresh(probe).wait_for_message("/map", timeout_s=START_S,
                                             predicate=lambda msg: msg["header"]["stamp"] > 0)
        assert cells(grid) == slam_like
        assert (grid["info"]["origin"]["position"]["x"], grid["info"]["origin"]["position"]["y"]) == (-2.0, -3.0)
        assert read_map_as_a_student(ros_master.env) == {"grid": slam_like, "free": 8, "walls": 4, "unknown": 3,
                                                         "origin": [-2.0, -3.0]}
    finally:
        server.stop()


def test_under_sim_time_the_map_and_its_services_wait_for_the_clock(ros_master, maps, probe):
    parameters = rosgraph.Master("/test", master_uri=ros_master.uri)
    parameters.setParam("/use_sim_time", True)
    server = start_map_server(ros_master, str(maps / "room.yaml"))
    try:
        wait_for_topic(ros_master.uri, "/map")
        assert fresh(probe).collect("/map", 1.5) == []
        assert service_uri(ros_master.uri, "/static_map") is None   # no empty map for a caller meanwhile
        probe.publish("/clock", "rosgraph_msgs/Clock", {"clock": {"secs": 42, "nsecs": 5000000}})
        grid = probe.wait_for_message("/map", timeout_s=START_S)
        assert grid["header"]["stamp"] == grid["info"]["map_load_time"] == pytest.approx(42.005)
    finally:
        server.stop()
        parameters.deleteParam("/use_sim_time")
