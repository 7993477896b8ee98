"""turtlebot3_gazebo's Python side: the turtlebot3_drive demo's decisions (obstacle_avoider, no ROS) and its
node (drive_node, the only module that imports rospy)."""
from turtlebot3_gazebo.obstacle_avoider import Command, DriveError, ObstacleAvoider, Ranges, State

__all__ = ["Command", "DriveError", "ObstacleAvoider", "Ranges", "State"]
