#!/usr/bin/env python3
"""COM2009 Assignment #1 Part 6 Exercise 4: follow the pink line on the floor with the camera.

Run it in `roslaunch tuos_simulations line_following.launch` (or line_following_setup.launch).
Each frame from /camera/rgb/image_raw: keep the rows that show the floor 0.3-0.5 m ahead, threshold them in HSV
for the line's colour (~colour, default pink: the course's magenta #ff00ff), take the mask's centroid and steer it
onto the robot's centre line with a proportional controller (week6_vision.line_following), driving at ~linear
m/s (default 0.1). The robot turns on the spot until it first sees the line, and stops over the line's end
(it drives on blind for the 0.37 m between its centre and the floor the camera watches once the line is gone);
it drives straight over marks across the line (the START and FINISH bars).
~gain (1.5: rad/s per half image width of error), ~max_angular (1.0 rad/s).
Publishes /cmd_vel; a zero Twist on shutdown (Ctrl-C).
"""
import rospy

from week6_vision.colour_masks import centroid, colour_mask, colour_name, column_span
from week6_vision.floor_view import centre_line_column, floor_rows
from week6_vision.line_following import LineFollowing
from week6_vision.ros_node import bgr_image, run, subscribe_camera, twist, velocity_publisher

NEAR_M, FAR_M = 0.3, 0.5     # the stretch of floor ahead of the camera that the follower looks at


class LineFollower:
    def __init__(self):
        self.colour = colour_name(rospy.get_param("~colour", "pink"))
        self.follow = LineFollowing(linear=rospy.get_param("~linear", 0.1), gain=rospy.get_param("~gain", 1.5),
                                    max_angular=rospy.get_param("~max_angular", 1.0))
        self.status = None
        self.cmd_vel = velocity_publisher()
        subscribe_camera(self.on_image)

    def on_image(self, message):
        image = bgr_image(message)
        if image is None:
            return
        height, width = image.shape[:2]
        first, end = floor_rows(width, height, NEAR_M, FAR_M)
        mask = colour_mask(image[first:end], self.colour)
        line = centroid(mask)
        target_x = centre_line_column(width, (NEAR_M + FAR_M) / 2)
        command = self.follow.command(None if line is None else line[0], target_x, width,
                                      message.header.stamp.to_sec(), span=column_span(mask))
        if command.status != self.status:
            rospy.loginfo(f"Line follower: {command.status}.")
            self.status = command.status
        self.cmd_vel.publish(twist(command.linear, command.angular))


if __name__ == "__main__":
    run("line_follower", LineFollower)
