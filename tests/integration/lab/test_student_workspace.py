"""The student's own workspace, as the course pages walk it, in a real interactive bash (a pseudo-terminal):
a new terminal creates ~/catkin_ws as an overlay of the lab; the Week 4 page's steps (catkin_create_pkg,
a server file, catkin build, source, roscd, rosrun, rosservice call with Tab) run the student's own server;
a student package shadows the lab's package of the same name until it is removed; `source ~/.bashrc` that
puts a pyenv-like python3 first breaks rosrun until `src` repairs the terminal. Without a terminal: catkin_make
builds the created workspace too, LAB_STUDENT_WS opts out or points elsewhere, and a workspace built without
the lab underneath is left out. HOME is a temporary folder."""
import subprocess
from pathlib import Path

import pytest

from roslab.terminal import Terminal, student_env

REPO_ROOT = Path(__file__).resolve().parents[3]
LAB_DEVEL = REPO_ROOT / "catkin_ws" / "devel"

MOVE_SERVER = '''#!/usr/bin/env python3
import rospy
from tuos_ros_msgs.srv import SetBool, SetBoolResponse

service_name = "move_service"


def callback_function(service_request):
    service_response = SetBoolResponse()
    service_response.response_signal = service_request.request_signal
    service_response.response_message = "my part4_services server got {}".format(service_request.request_signal)
    return service_response


rospy.init_node(f"{service_name}_server")
my_service = rospy.Service(service_name, SetBool, callback_function)
rospy.loginfo(f"the '{service_name}' Server is ready to be called...")
rospy.spin()
'''
"""The student's server, after the Week 4 page's move_server.py (no robot needed: it answers at once)."""

SHADOWING_SERVER = '''#!/usr/bin/env python3
print("this is the student's own week4_services/move_server.py")
'''

PYENV_INIT = 'export PATH="$HOME/.pyenv/shims:$PATH"   # what `eval "$(pyenv init -)"` does\n'


@pytest.fixture(scope="module")
def home(tmp_path_factory):
    """A student's home whose .bashrc makes every terminal a ROS terminal of this lab."""
    home = tmp_path_factory.mktemp("student")
    (home / ".bashrc").write_text("source {}\n".format(REPO_ROOT / "scripts" / "env.sh"))
    shims = home / ".pyenv" / "shims"
    shims.mkdir(parents=True)
    (shims / "python3").write_text('#!/bin/sh\nexec /usr/bin/python3 -E -S "$@"\n')   # no ROS modules
    (shims / "python3").chmod(0o755)
    return home


@pytest.fixture
def part4_services(home):
    """The Week 4 page's package in the student's workspace, built. The Week 4 test builds it in a terminal
    when it runs first; a test run on its own gets it built here."""
    if not (home / "catkin_ws/devel/share/part4_services").exists():
        in_bash("cd ~/catkin_ws/src && catkin_create_pkg part4_services rospy geometry_msgs tuos_ros_msgs", home)
        write_executable(home / "catkin_ws/src/part4_services/src/move_server.py", MOVE_SERVER)
        in_bash("cd ~/catkin_ws && catkin build part4_services", home)
    return home / "catkin_ws/src/part4_services"


def write_executable(path, text):
    path.write_text(text)
    path.chmod(0o755)


@pytest.fixture(scope="module")
def terminals(ros_master, home, tmp_path_factory):
    """A function that opens a new terminal of the student (bash -i in the home folder); every terminal it
    opened is closed after the module."""
    logs = tmp_path_factory.mktemp("terminals")
    env = student_env(home, ROS_MASTER_URI=ros_master.uri, ROS_HOSTNAME="localhost")
    opened = []

    def open_terminal():
        opened.append(Terminal(env, home, logs / "terminal-{}.log".format(len(opened))))
        return opened[-1]
    yield open_terminal
    for terminal in opened:
        terminal.close()


@pytest.fixture(scope="module")
def terminal(terminals):
    return terminals()


def test_the_first_terminal_creates_the_workspace_as_an_overlay_of_the_lab(home, terminal):
    workspace = home / "catkin_ws"
    assert "created your catkin workspace {}".format(workspace) in terminal.startup
    assert (workspace / "src" / "CMakeLists.txt").resolve().name == "toplevel.cmake", "catkin_make's layout"
    config = terminal.run("catkin config --workspace ~/catkin_ws")
    assert "Extending:        [explicit] {}".format(LAB_DEVEL) in config, config


def test_the_week4_page_with_the_students_own_server(home, terminals, terminal):
    output = terminal.run("cd ~/catkin_ws/src && catkin_create_pkg part4_services rospy geometry_msgs tuos_ros_msgs")
    assert "Successfully created files" in output, output
    (home / "catkin_ws/src/part4_services/src/move_server.py").write_text(MOVE_SERVER)
    terminal.run("chmod +x part4_services/src/move_server.py")   # as the page says
    output = terminal.run("cd ~/catkin_ws && catkin build", timeout_s=300)
    assert "[build] Summary: All" in output and "succeeded!" in output, output[-2000:]
    terminal.run("source ~/catkin_ws/devel/setup.bash")

    terminal.type("roscd part4_ser")
    terminal.tab("part4_services/")
    terminal.enter()
    assert terminal.run("pwd").strip() == str(home / "catkin_ws/src/part4_services")

    server = terminals()
    server.type("rosrun part4_services move_server.py\r")
    server.wait_for("the 'move_service' Server is ready to be called")

    terminal.type("rosservice call /move_service ")
    terminal.tab('"request_signal: false" ')
    reply = terminal.enter()
    assert reply.split() == ["response_signal:", "False", "response_message:", '"my', "part4_services", "server",
                             "got", 'False"'], reply
    reply = terminal.run('rosservice call /move_service "request_signal: true"')
    assert 'response_message: "my part4_services server got True"' in reply, reply
    server.interrupt()


def test_a_new_terminal_has_the_students_overlay_on_top(home, part4_services, terminals):
    terminal = terminals()
    assert terminal.run("rospack find part4_services").strip() == str(part4_services)
    assert terminal.run("rospack find week4_services").strip() == str(
        REPO_ROOT / "catkin_ws/src/exercises/week4_services"), "the lab's packages stay available"
    assert terminal.run("echo $CMAKE_PREFIX_PATH").strip() == "{}:{}".format(home / "catkin_ws/devel", LAB_DEVEL)


def test_a_students_package_shadows_the_labs_until_it_is_removed(home, part4_services, terminal):
    lab_package = REPO_ROOT / "catkin_ws/src/exercises/week4_services"
    terminal.run("cd ~/catkin_ws/src && catkin_create_pkg week4_services rospy")
    write_executable(home / "catkin_ws/src/week4_services/src/move_server.py", SHADOWING_SERVER)
    output = terminal.run("cd ~/catkin_ws && catkin build && src", timeout_s=300)
    assert "[build] Summary: All" in output and "succeeded!" in output, output[-2000:]
    assert terminal.run("rospack find week4_services").strip() == str(home / "catkin_ws/src/week4_services")
    assert terminal.run("rosrun week4_services move_server.py").strip() == \
        "this is the student's own week4_services/move_server.py"

    output = terminal.run("rm -r ~/catkin_ws/src/week4_services && catkin clean --orphans -y && src", timeout_s=300)
    assert terminal.run("rospack find week4_services").strip() == str(lab_package), output
    executable = terminal.run("rosrun --prefix echo week4_services move_server.py").strip()
    assert executable.startswith(str(REPO_ROOT / "catkin_ws") + "/"), executable   # the source or its devel relay
    assert terminal.run("rospack find part4_services").strip() == str(part4_services)


def test_src_repairs_a_terminal_after_source_bashrc_put_pyenv_first(ros_master, home, part4_services, terminal):
    with (home / ".bashrc").open("a") as bashrc:
        bashrc.write(PYENV_INIT)
    try:
        terminal.run("source ~/.bashrc")
        assert terminal.run("command -v python3").strip() == str(home / ".pyenv/shims/python3")
        output = terminal.run("rosrun part4_services move_server.py")
        assert "No module named 'rospy'" in output, output

        terminal.run("src")
        assert terminal.run("command -v python3").strip() == str(REPO_ROOT / ".venv/bin/python3")
        terminal.type("rosrun part4_services move_server.py\r")
        terminal.wait_for("the 'move_service' Server is ready to be called")
        reply = subprocess.run(["rosservice", "call", "/move_service", "request_signal: true"], env=ros_master.env,
                               stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, timeout=30).stdout
        assert "my part4_services server got True" in reply, reply
        terminal.interrupt()
        assert terminal.run("rospack find part4_services").strip() == str(part4_services)
    finally:
        (home / ".bashrc").write_text((home / ".bashrc").read_text().replace(PYENV_INIT, ""))


def in_bash(script, home, **env):
    """`script` after `source scripts/env.sh` in a non-interactive bash with a fresh environment."""
    result = subprocess.run(["bash", "-c", "source scripts/env.sh && " + script], cwd=REPO_ROOT,
                            env=student_env(home, **env), stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                            timeout=300)
    assert result.returncode == 0, result.stdout
    return result.stdout


def test_lab_student_ws_off_leaves_the_home_alone(tmp_path):
    output = in_bash('echo "$CMAKE_PREFIX_PATH"', tmp_path, LAB_STUDENT_WS="off")
    assert output.strip() == str(LAB_DEVEL)
    assert list(tmp_path.iterdir()) == []


def test_lab_student_ws_points_elsewhere(tmp_path):
    elsewhere = tmp_path / "courses" / "com2009_ws"
    output = in_bash("catkin config --workspace {} | grep Extending".format(elsewhere), tmp_path / "home",
                     LAB_STUDENT_WS=str(elsewhere))
    assert "created your catkin workspace {}".format(elsewhere) in output
    assert "[explicit] {}".format(LAB_DEVEL) in output
    assert not (tmp_path / "home" / "catkin_ws").exists()


def test_the_created_workspace_builds_with_catkin_make_too(tmp_path):
    in_bash("cd ~/catkin_ws/src && catkin_create_pkg part4_services rospy tuos_ros_msgs", tmp_path)
    write_executable(tmp_path / "catkin_ws/src/part4_services/src/move_server.py", MOVE_SERVER)
    in_bash("cd ~/catkin_ws && catkin_make", tmp_path)
    output = in_bash("rospack find part4_services && rosrun --prefix echo part4_services move_server.py", tmp_path)
    assert output.split() == [str(tmp_path / "catkin_ws/src/part4_services"),
                              str(tmp_path / "catkin_ws/src/part4_services/src/move_server.py")]


def test_a_workspace_built_without_the_lab_underneath_is_left_out(tmp_path):
    """Built by catkin_make in a terminal that had no lab sourced: sourcing it would hide every lab package."""
    workspace = tmp_path / "catkin_ws"
    (workspace / "src").mkdir(parents=True)
    build = subprocess.run(["bash", "-c", "catkin_init_workspace src && catkin_make"], cwd=workspace,
                           env=student_env(tmp_path), stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                           timeout=300)
    assert build.returncode == 0, build.stdout
    output = in_bash('echo "$ROS_PACKAGE_PATH"', tmp_path)
    assert "{} was built without the lab underneath".format(workspace) in output
    assert output.splitlines()[-1] == str(REPO_ROOT / "catkin_ws/src")

    in_bash("cd ~/catkin_ws && rm -r build devel && catkin_make", tmp_path)   # the advice, in a ROS terminal
    output = in_bash('echo "$ROS_PACKAGE_PATH"', tmp_path)
    assert output.strip() == "{}:{}".format(workspace / "src", REPO_ROOT / "catkin_ws/src")


def test_a_terminal_opened_before_the_first_build_finds_the_students_package_at_once(tmp_path):
    """The Week 4 same-name trap: the page's TERMINAL 3, opened before the first `catkin build` (here: before the
    package exists, after a rospack call that filled rospack's cache), `roscd week4_services` and writes the new file
    there. The student's unbuilt workspace is first on the package path and rospack does not trust its cache, so the
    file lands in the student's package, never in the lab's."""
    lab_package = REPO_ROOT / "catkin_ws/src/exercises/week4_services"
    student_package = tmp_path / "catkin_ws/src/week4_services"
    output = in_bash("rospack find week4_services && cd ~/catkin_ws/src && catkin_create_pkg week4_services rospy "
                     ">/dev/null && roscd week4_services && touch src/new_server.py && pwd && "
                     "rospack find week4_services", tmp_path)
    assert output.split()[-3:] == [str(lab_package), str(student_package), str(student_package)], output
    assert (student_package / "src/new_server.py").exists()
    assert not (lab_package / "src/new_server.py").exists()


def test_terminal_3_of_the_week4_page_before_the_first_build_writes_and_runs_the_students_file(tmp_path):
    """The Week 4 page's TERMINAL 3, opened before the student's first `catkin build` (and before the student's
    package existed, when roscd went to the lab's reference package and said so): `roscd week4_services/src`,
    a new move_client.py there, `rosrun week4_services move_client.py`. The file lands in the student's package,
    none in the lab's src folder, and rosrun runs it at once, with no "non-unique executable" menu between it and
    the lab's relay of its own move_client.py."""
    lab_src = REPO_ROOT / "catkin_ws/src/exercises/week4_services/src"
    lab_before = sorted(lab_src.iterdir())
    (tmp_path / ".bashrc").write_text("source {}\n".format(REPO_ROOT / "scripts" / "env.sh"))
    env = student_env(tmp_path)
    terminal_1 = Terminal(env, tmp_path, tmp_path / "terminal-1.log")
    terminal_3 = Terminal(env, tmp_path, tmp_path / "terminal-3.log")
    try:
        output = terminal_3.run("roscd week4_services/src")   # no package of the student's yet: the lab's, said once
        assert output.count("note: ") == 1 and f"note: {lab_src} is the lab's reference package week4_services" in \
            output and "catkin_create_pkg week4_services" in output, output
        assert terminal_3.run("roscd tb3_sim && cd") == ""   # the lab's simulators are not exercises: no note
        output = terminal_1.run("cd ~/catkin_ws/src && catkin_create_pkg week4_services rospy geometry_msgs")
        assert "Successfully created files" in output, output
        output = terminal_3.run("roscd week4_services/src && touch move_client.py && chmod +x move_client.py && pwd")
        assert output.strip() == str(tmp_path / "catkin_ws/src/week4_services/src"), output
        terminal_3.run("printf '#!/usr/bin/env python3\\nprint(\"the student client\")\\n' > move_client.py")
        output = terminal_3.run("rosrun week4_services move_client.py")
        assert output.strip() == "the student client", output
    finally:
        terminal_1.close()
        terminal_3.close()
    assert sorted(lab_src.iterdir()) == lab_before
