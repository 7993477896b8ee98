"""The turtlesim model without ROS: turtles, their motion, the pen canvas (a QImage, as the original draws
it), services as plain methods, and the logic of the tutorial nodes (draw_square, teleop keys)."""
