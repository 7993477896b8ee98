"""The amcl stand-in: a thin rospy node over lab_nav.localization."""
