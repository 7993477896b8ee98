"""turtlesim: a Python replica of ROS 1 turtlesim. Layers: `core` (no rospy), `ros` (the nodes), `view` (Qt
window), `tools` (terminal input). The generated turtlesim.msg and turtlesim.srv join this package."""
