# The one list of the COM2009 course interfaces. Included by tuos_msgs and by the older course years'
# packages com2009_msgs and tuos_ros_msgs, whose msg/srv/action folders are symlinks to tuos_msgs's, so
# all three generate identical classes (same md5sums) from one set of definition files.
find_package(catkin REQUIRED COMPONENTS message_generation std_msgs actionlib_msgs)

add_message_files(FILES NumpyFloat32Array.msg NumpyInt32Array.msg)
add_service_files(FILES SetBool.srv TimedMovement.srv Approach.srv)
add_action_files(FILES CameraSweep.action Search.action)
generate_messages(DEPENDENCIES std_msgs actionlib_msgs)

catkin_package(CATKIN_DEPENDS message_runtime std_msgs actionlib_msgs)
