"""`rosrun rqt_graph rqt_graph`: the running graph read once from the master, drawn by Graphviz's dot.

With a display the picture opens in a window titled rqt_graph (close it or press Ctrl-C to end). Without one it is
written to rosgraph.png in the current folder (where rqt_graph's own export would go), and one line gives its path
and the browser view, whose graph panel stays live. No ROS node is registered: the master's system state is read through
rosgraph's API, as rosnode and rostopic read it.
"""
import signal
import subprocess
import sys
from pathlib import Path

import rosgraph
from window_hint import display_problem, no_display_line

from rqt_graph.dot_graph import node_graph, to_dot

OUTPUT_NAME = "rosgraph.png"
DOT_TIMEOUT_S = 30
SIGNAL_CHECK_MS = 200
COMMAND = "rosrun rqt_graph rqt_graph"


class GraphError(Exception):
    """The graph could not be read or drawn; the text says why and what to do."""


def read_graph():
    """The node graph of the master at $ROS_MASTER_URI."""
    master = rosgraph.Master("/rqt_graph")
    try:
        publishers, subscribers, _ = master.getSystemState()
    except (OSError, rosgraph.MasterException) as error:
        raise GraphError(f"cannot reach the ROS master at {master.master_uri} ({error}): start roscore "
                         "first") from None
    return node_graph(publishers, subscribers)


def render_png(dot_text):
    """PNG bytes of the DOT text, from Debian's graphviz."""
    try:
        result = subprocess.run(["dot", "-Tpng"], input=dot_text.encode(), stdout=subprocess.PIPE,
                                stderr=subprocess.PIPE, timeout=DOT_TIMEOUT_S, check=False)
    except FileNotFoundError:
        raise GraphError("Graphviz's dot is not installed: sudo apt-get install graphviz") from None
    if result.returncode != 0:
        raise GraphError(f"dot failed: {result.stderr.decode(errors='replace').strip()}")
    return result.stdout


def show_window(png):
    """The picture in a scrollable Qt window until it is closed."""
    from PyQt5.QtCore import QTimer
    from PyQt5.QtGui import QPixmap
    from PyQt5.QtWidgets import QApplication, QLabel, QScrollArea

    app = QApplication([COMMAND])
    pixmap = QPixmap()
    pixmap.loadFromData(png, "PNG")
    label = QLabel()
    label.setPixmap(pixmap)
    window = QScrollArea()
    window.setWidget(label)
    window.setWindowTitle("rqt_graph")
    window.resize(min(pixmap.width() + 20, 1600), min(pixmap.height() + 20, 1000))
    window.show()
    signal.signal(signal.SIGINT, lambda *_: app.quit())   # Ctrl-C closes it, as rqt's own window
    wake_python = QTimer()   # Qt's loop lets Python run its signal handlers only between events
    wake_python.start(SIGNAL_CHECK_MS)
    wake_python.timeout.connect(lambda: None)
    app.exec_()


def main(args):
    try:
        graph = read_graph()
        png = render_png(to_dot(graph))
        problem = display_problem()
        if problem is None:
            show_window(png)
            return 0
        path = Path.cwd() / OUTPUT_NAME
        try:
            path.write_bytes(png)
        except OSError as error:
            raise GraphError(f"cannot write {path}: {error.strerror}; run it from a folder you can write to") \
                from None
    except GraphError as error:
        print(f"[rqt_graph] {error}", file=sys.stderr)
        return 1
    written = f"the graph ({len(graph.nodes)} nodes, {len(graph.edges)} connections) is written to {path}"
    print(no_display_line("rqt_graph", problem, COMMAND, instead=written), file=sys.stderr, flush=True)
    return 0
