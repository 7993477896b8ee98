"""Sample submissions for the grader's tests, made from the lab's own Week 4 reference package (never from real
students' code): the reference as it is, copies with one typical mistake each, written as a student would make
it, copies that misbehave on purpose against the sandbox (hostile_code.py), and packages written from scratch
(student_style/): one in a student's own style, one in the course template's habits (week4_course_template:
whole-second timing, module-level publishers, bare return values, the older message packages, other file names,
two exercises on one service name). `make_submission(name, folder)` writes one into `folder/<name>/`."""
import re
import shutil
from pathlib import Path
from typing import Dict, Optional

from .hostile_code import FORKS_CHILDREN, PRINTS_MEGABYTES, REACHES_NETWORK, SNOOPS

HERE = Path(__file__).resolve().parent
REFERENCE = HERE.parents[2] / "catkin_ws" / "src" / "exercises" / "week4_services"
PART5_REFERENCE = HERE.parents[2] / "catkin_ws" / "src" / "exercises" / "week5_actions"
PART6_REFERENCE = HERE.parents[2] / "catkin_ws" / "src" / "exercises" / "week6_vision"
# Written from scratch, not from the reference: {name: the package folder}.
FROM_SCRATCH = {"student_style": HERE / "student_style" / "week4_alice",
                "course_template": HERE / "student_style" / "week4_course_template",
                "part6_course_template": HERE / "student_style" / "part6_course_template"}

PLACEHOLDER = re.compile(r"@[A-Z_]+@")
MOVE_MAIN = "def main():\n    rospy.init_node(NODE_NAME)\n"


def misbehaves_at_start(code: str, call: str):
    """The move server with `code` (functions) added and `call` made first thing in main()."""
    return {"nodes/move_server.py": [(MOVE_MAIN, code + "\n\n" + MOVE_MAIN.replace("main():\n", "main():\n    "
                                                                                  + call + "\n"))]}


MISTAKES = {
    # name: {file in the package: [(text in the reference, what the student wrote instead)]}
    "reference": {},
    "wrong_direction": {"nodes/move_server.py": [("FORWARD_SPEED_MPS = 0.1", "FORWARD_SPEED_MPS = -0.1")]},
    "old_message_package": {"nodes/move_server.py": [("from tuos_msgs.srv", "from com2009_msgs.srv")],
                            "package.xml": [("<depend>tuos_msgs</depend>",
                                             "<depend>tuos_msgs</depend>\n  <depend>com2009_msgs</depend>")]},
    "does_not_build": {"CMakeLists.txt": [("catkin_python_setup()", "catkin_python_setup(\n")]},
    "hangs_in_the_callback": {"nodes/move_server.py": [
        ("        if not request.request_signal:",
         "        rospy.sleep(1e6)\n        if not request.request_signal:")]},
    "busy_waits": {"nodes/move_server.py": [
        ("        if not request.request_signal:", "        while True:\n            pass\n"
                                                    "        if not request.request_signal:")]},
    # The timed move drives for twice the duration asked for.
    "wrong_duration": {"nodes/timed_move_server.py": [("request.movement_request, request.duration,",
                                                       "request.movement_request, request.duration * 2,")]},
    # The "stop" after the move is a copy of the line that started it: the robot keeps driving.
    "never_stops": {"nodes/move_server.py": [
        ("        elapsed = (rospy.get_rostime() - start_time).to_sec()",
         "        self.robot.drive(FORWARD_SPEED_MPS, 0.0)  # stop the robot\n"
         "        elapsed = (rospy.get_rostime() - start_time).to_sec()")]},
    # Any word drives forwards, any duration is taken as it is (0 and -2 s reply True at once).
    "ignores_invalid_input": {"nodes/timed_move_server.py": [
        ("from tb3_client.robot import", "from tb3_client.motion import Motion\nfrom tb3_client.robot import"),
        ("            motion = timed_movement(request.movement_request, request.duration,\n"
         "                                    self.linear_speed, self.angular_speed)",
         "            speeds = {\"fwd\": (self.linear_speed, 0.0), \"back\": (-self.linear_speed, 0.0),\n"
         "                      \"left\": (0.0, self.angular_speed), \"right\": (0.0, -self.angular_speed)}\n"
         "            linear, angular = speeds.get(request.movement_request, (self.linear_speed, 0.0))\n"
         "            motion = Motion(linear, angular, request.duration)")]},
    # Bare values instead of Response objects: rospy converts a tuple of every field, and a single value when the
    # response has one field (TimedMovement's success), but not one value for SetBool's two fields.
    "bare_values": {
        "nodes/move_server.py": [
            ("return SetBoolResponse(False, \"Nothing happened: set request_signal to 'true' to move the robot.\")",
             "return False, \"Nothing happened: set request_signal to 'true' to move the robot.\""),
            ("return SetBoolResponse(True, \"Request complete: the robot moved forwards for {:.1f} seconds.\""
             ".format(elapsed))", "return True")],
        "nodes/timed_move_server.py": [("return TimedMovementResponse(False)", "return False"),
                                       ("return TimedMovementResponse(True)", "return True")]},
    "own_service_names": {"nodes/move_server.py": [("\"move_service\"", "\"my_move_service\"")],
                          "nodes/timed_move_server.py": [("\"timed_move_service\"", "\"my_timed_move_service\"")],
                          "nodes/approach_server.py": [("\"approach_service\"", "\"my_approach_service\"")]},
    "python2_syntax": {"nodes/move_server.py": [
        (MOVE_MAIN, MOVE_MAIN.replace("main():\n", "main():\n    print \"Starting the move server...\"\n"))]},
    # Hostile on purpose (hostile_code.py); each still serves /move_service like the reference once it has tried.
    "forks_children": misbehaves_at_start(FORKS_CHILDREN, "leave_children_behind()"),
    "reaches_network": misbehaves_at_start(REACHES_NETWORK, "try_the_network()"),
    "snoops": misbehaves_at_start(SNOOPS, "snoop()"),
    "prints_megabytes": misbehaves_at_start(PRINTS_MEGABYTES, "shout()"),
}


PART5_MISTAKES = {
    # name: {file in week5_actions: [(text in the reference, what the student wrote instead)]}
    "part5_reference": {},
    # The sweep writes the message's format text instead of the image; the Search server sends no feedback, and
    # after its result it "keeps searching": the robot drives on.
    "part5_careless": {"nodes/action_server.py": [
        ("        self.save(image_message, path)\n", "        path.write_text(image_message.format)\n")],
                       "nodes/search_server.py": [
        ("                                         on_sweep=lambda travelled: self.server.publish_feedback(\n"
         "                                             SearchFeedback(travelled)),\n", ""),
        ("        self.server.publish_feedback(SearchFeedback(result.total_distance_travelled))\n", ""),
        ("            rospy.loginfo(text)\n", "            rospy.loginfo(text)\n"
                                             "            self.robot.drive(plan.velocity, 0.0)  # keep searching\n")]},
}


PART6_MISTAKES = {
    # name: {file in week6_vision: [(text in the reference, what the student wrote instead)]}
    "part6_reference": {},
    # The colour search masks every colour with red's threshold (it stops facing the red pillar whatever it looks
    # for); the line follower steers nowhere: it drives straight on from START.
    "part6_careless": {"nodes/colour_search.py": [("colour_mask(image, colour)", "colour_mask(image, \"red\")")],
                       "nodes/line_follower.py": [("twist(command.linear, command.angular)",
                                                   "twist(command.linear, 0.0)")]},
}
# Each reference package and the sample submissions made from it.
REFERENCES = ((REFERENCE, MISTAKES), (PART5_REFERENCE, PART5_MISTAKES), (PART6_REFERENCE, PART6_MISTAKES))


SELF_CONTAINED = tuple(name for name, changes in MISTAKES.items()
                       if not any(PLACEHOLDER.search(new) for replacements in changes.values()
                                  for _, new in replacements)) + ("student_style", "course_template")
"""The Week 4 samples that need no `fill` (every one but those whose hostile code needs the test's paths and
addresses): what a benchmark can grade as a class."""


def make_submission(name: str, folder: Path, fill: Optional[Dict[str, str]] = None) -> Path:
    """The submission `name` (a key of MISTAKES, PART5_MISTAKES, PART6_MISTAKES or FROM_SCRATCH) as a student folder
    holding the package (week4_services, week5_actions for Part 5, week6_vision for Part 6); returns the folder.
    `fill` replaces placeholders (hostile_code.py's @NAME@) in the files the mistake changed."""
    student = Path(folder) / name
    if name in FROM_SCRATCH:
        shutil.copytree(FROM_SCRATCH[name], student / FROM_SCRATCH[name].name,
                        ignore=shutil.ignore_patterns("__pycache__", "*.pyc"))
        return student
    reference, mistakes = next((folder, table) for folder, table in REFERENCES if name in table)
    package = student / reference.name
    shutil.copytree(reference, package, ignore=shutil.ignore_patterns("__pycache__", "*.pyc"))
    for relative, replacements in mistakes[name].items():
        path = package / relative
        text = path.read_text()
        for old, new in replacements:
            assert old in text, "the reference changed: {} no longer has {!r}".format(relative, old)
            text = text.replace(old, new, 1)
        for placeholder, value in (fill or {}).items():
            text = text.replace(placeholder, value)
        assert not PLACEHOLDER.search(text), "{}: {} was not filled".format(relative, PLACEHOLDER.search(text))
        path.write_text(text)
    return student
