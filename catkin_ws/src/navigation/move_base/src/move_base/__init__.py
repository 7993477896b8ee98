"""The move_base stand-in: thin rospy layers over lab_nav.costmap and lab_nav.planning."""
