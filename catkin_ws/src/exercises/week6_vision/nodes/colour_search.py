#!/usr/bin/env python3
"""COM2009 Assignment #1 Part 6 Exercise 3: turn on the spot and stop facing each coloured pillar in turn.

Run it in `roslaunch tuos_simulations coloured_pillars.launch`. ~colours (default "red,green,turquoise,blue": the
exercise's task, every pillar, in the order the robot meets them turning from its start; "blue" is the course's
own node's one target) are looked for one after the other: the robot turns
anticlockwise at ~turn_speed (0.4 rad/s) until the colour is in view (an HSV threshold on each frame from
/camera/rgb/image_raw, week6_vision.colour_masks), turns the blob's centroid to the middle of the image, stops,
prints "SEARCH COMPLETE: The robot is now facing the <colour> pillar.", waits ~pause (2 s) and looks for the next.
A colour not found within a turn and a quarter is skipped with a warning. After the last colour the node stops
the robot and exits. Publishes /cmd_vel; a zero Twist on shutdown (Ctrl-C).
"""
import rospy

from week6_vision.colour_masks import centroid, colour_mask, colour_name
from week6_vision.pillar_search import ColourSearch
from week6_vision.ros_node import bgr_image, run, subscribe_camera, twist, velocity_publisher


class ColourSearchNode:
    def __init__(self):
        wanted = str(rospy.get_param("~colours", "red,green,turquoise,blue"))
        colours = [colour_name(c) for c in wanted.split(",") if c.strip()]
        self.search = ColourSearch(colours, turn_speed=rospy.get_param("~turn_speed", 0.4),
                                   pause_s=rospy.get_param("~pause", 2.0))
        self.cmd_vel = velocity_publisher()
        subscribe_camera(self.on_image)
        rospy.loginfo(f"Colour search: looking for {', '.join(colours)}.")

    def on_image(self, message):
        colour = self.search.target
        image = None if colour is None else bgr_image(message)
        if image is None:
            return
        width = image.shape[1]
        blob = centroid(colour_mask(image, colour))
        offset = None if blob is None else (blob[0] - (width - 1) / 2) / (width / 2)
        step = self.search.update(offset, message.header.stamp.to_sec())
        self.cmd_vel.publish(twist(angular=step.angular))
        if step.event and step.event.startswith("facing"):
            rospy.loginfo(f"SEARCH COMPLETE: The robot is now facing the {colour} pillar.")
        elif step.event:
            rospy.logwarn(f"Colour search: {step.event}.")
        if step.done:
            rospy.signal_shutdown("every colour searched")


if __name__ == "__main__":
    run("colour_search", ColourSearchNode)
