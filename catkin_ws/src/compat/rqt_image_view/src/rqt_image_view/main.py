"""`rosrun rqt_image_view rqt_image_view [TOPIC]` as Debian's image_view on TOPIC.

rqt_image_view picks its topic from a drop-down list; image_view needs it on the command line, so TOPIC defaults to
the TurtleBot3 Waffle's camera, /camera/rgb/image_raw, the topic the course's vision pages view. A topic ending in
/compressed or /theora is shown through that image_transport from its base topic, as rqt_image_view lists them.
ROS arguments (name:=value, __name:=...) pass through to image_view. Without a display: window_hint's one line.
"""
from window_hint.relay import load_redirects, run

DEFAULT_TOPIC = "/camera/rgb/image_raw"
TRANSPORTS = ("compressed", "theora")


def image_view_args(args):
    """image_view's arguments for rqt_image_view's: the first plain argument is the topic."""
    ros_args = [arg for arg in args if ":=" in arg]
    plain = [arg for arg in args if ":=" not in arg]
    topic = plain[0] if plain else DEFAULT_TOPIC
    base, _, last = topic.rpartition("/")
    if base and last in TRANSPORTS:
        return [f"image:={base}", f"_image_transport:={last}", *ros_args]
    return [f"image:={topic}", *ros_args]


def main(args):
    program = load_redirects()["image_view/image_view"].program
    command = " ".join(["rosrun rqt_image_view rqt_image_view", *args])
    return run(program, image_view_args(args), "rqt_image_view", command)
