"""tb3_client: the TurtleBot3 as course code sees it (like the course's own tb3.py helper).

`scan_ahead` (plain Python): the closest object ahead in a LaserScan. `robot` (rospy): /cmd_vel out, /odom
and /scan in, waiting in rospy time with a watchdog that notices a dead simulator.
"""
