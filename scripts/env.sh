# Source me: `source scripts/env.sh` turns this terminal into a ROS 1 terminal for this workspace.
#
# - Debian's /usr/bin/python3 (through the project venv in .venv, which sees Debian's ROS modules) comes first
#   on PATH, ahead of any pyenv/conda python3 that cannot import rospy and breaks catkin_make.
# - The workspace overlay catkin_ws/devel/setup.bash is sourced (run scripts/setup first if it is missing).
# - ROS is bound to this machine only unless you chose otherwise before sourcing: ROS_HOSTNAME=localhost and
#   ROS_MASTER_URI=http://localhost:11311 are set only when you have not set ROS_MASTER_URI, ROS_HOSTNAME or
#   ROS_IP yourself. ROS 1 has no authentication: opening it to a network opens the robot to that network.
#   roscpp nodes (rosout too) would still listen on every interface; the ros_loopback package's bind()
#   wrapper, preloaded here, keeps them on loopback whenever ROS is bound to localhost.
# - The course's aliases: src (re-source this file), tb3_empty_world and tb3_world (when their launch files exist).
#
# Safe to source more than once.

if [ -n "${BASH_SOURCE[0]:-}" ]; then
    _lab_env_file="${BASH_SOURCE[0]}"
else
    _lab_env_file="$0"   # zsh
fi
LAB_ROOT="$(cd "$(dirname "$_lab_env_file")/.." && pwd)"
export LAB_ROOT
unset _lab_env_file

_lab_user_master="${ROS_MASTER_URI:-}"
_lab_user_hostname="${ROS_HOSTNAME:-}"
_lab_user_ip="${ROS_IP:-}"

# The venv first, once: its python3 is Debian's interpreter with Box2D and pytest added.
case ":$PATH:" in
    *":$LAB_ROOT/.venv/bin:"*) ;;
    *) export PATH="$LAB_ROOT/.venv/bin:$PATH" ;;
esac
export VIRTUAL_ENV="$LAB_ROOT/.venv"
hash -r 2>/dev/null

if [ -f "$LAB_ROOT/catkin_ws/devel/setup.bash" ]; then
    if [ -n "${ZSH_VERSION:-}" ]; then
        source "$LAB_ROOT/catkin_ws/devel/setup.zsh"
    else
        source "$LAB_ROOT/catkin_ws/devel/setup.bash"
    fi
else
    echo "scripts/env.sh: the workspace is not built yet; run scripts/setup first." >&2
fi

if [ -z "$_lab_user_master$_lab_user_hostname$_lab_user_ip" ]; then
    export ROS_HOSTNAME=localhost
    export ROS_MASTER_URI=http://localhost:11311
else
    [ -n "$_lab_user_master" ] && export ROS_MASTER_URI="$_lab_user_master"
fi
unset _lab_user_master _lab_user_hostname _lab_user_ip

_lab_loopback="$LAB_ROOT/catkin_ws/devel/lib/libros_loopback.so"
if [ -f "$_lab_loopback" ]; then
    case ":${LD_PRELOAD:-}:" in
        *":$_lab_loopback:"*) ;;
        *) export LD_PRELOAD="$_lab_loopback${LD_PRELOAD:+:$LD_PRELOAD}" ;;
    esac
fi
unset _lab_loopback

alias src="source '$LAB_ROOT/scripts/env.sh'"
_lab_tb3_launch="$LAB_ROOT/catkin_ws/src/compat/turtlebot3_gazebo/launch"
if [ -f "$_lab_tb3_launch/turtlebot3_empty_world.launch" ]; then
    alias tb3_empty_world='roslaunch turtlebot3_gazebo turtlebot3_empty_world.launch'
fi
if [ -f "$_lab_tb3_launch/turtlebot3_world.launch" ]; then
    alias tb3_world='roslaunch turtlebot3_gazebo turtlebot3_world.launch'
fi
unset _lab_tb3_launch
export TURTLEBOT3_MODEL="${TURTLEBOT3_MODEL:-waffle}"
