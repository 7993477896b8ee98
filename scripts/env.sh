# Source me: `source scripts/env.sh` turns this terminal into a ROS 1 terminal for this workspace.
#
# - Debian's /usr/bin/python3 (through the project venv in .venv, which sees Debian's ROS modules) comes first
#   on PATH, ahead of any pyenv/conda python3 that cannot import rospy and breaks catkin_make. Every time this
#   file is sourced, so the `src` alias repairs a terminal where `source ~/.bashrc` put another python3 first.
# - The lab's workspace overlay catkin_ws/devel/setup.bash is sourced (run scripts/setup first if it is missing),
#   then the student's workspace on top of it: $LAB_STUDENT_WS, default ~/catkin_ws. A package there shadows the
#   lab's package of the same name (the ROS overlay rule); the lab's stay available otherwise. The workspace is
#   created when it does not exist, as an overlay of the lab ready for `catkin build` (the course's command) or
#   `catkin_make`, and sourced once built; before its first build its src folder is put first on
#   ROS_PACKAGE_PATH (and, as a source-only workspace, on CMAKE_PREFIX_PATH, where rosrun and roslaunch look for
#   executables), and rospack's 60 s cache is off (ROS_CACHE_TIMEOUT=0 unless set), so a package created there
#   is found at once, also in a terminal opened before it existed. LAB_STUDENT_WS=off leaves it out;
#   LAB_STUDENT_WS=<folder> uses another folder.
# - bash: rosbash's roscd, rosls, rosed, roscp, rospd, rosd and the other ROS shell functions, with Tab
#   completion of ROS commands, packages, services and requests; in an interactive bash also Debian's
#   bash-completion (Tab completion for catkin and every other command).
# - ROS is bound to this machine only unless you chose otherwise before sourcing: ROS_HOSTNAME=localhost and
#   ROS_MASTER_URI=http://localhost:11311 are set only when you have not set ROS_MASTER_URI, ROS_HOSTNAME or
#   ROS_IP yourself. ROS 1 has no authentication: opening it to a network opens the robot to that network.
#   roscpp nodes (rosout too) would still listen on every interface; the ros_loopback package's bind()
#   wrapper, preloaded here, keeps them on loopback whenever ROS is bound to localhost.
# - rospy nodes read each inbound connection's handshake with a 3 s timeout instead of stalling for 60 s on an
#   idle one (rospy_handshake_timeout's sitecustomize, first on PYTHONPATH): the lab's one patch of ROS.
# - The course's aliases: src (re-source this file), tb3_empty_world and tb3_world (when their launch files exist).
#
# Safe to source more than once.

if [ -n "${BASH_SOURCE[0]:-}" ]; then
    _lab_env_file="${BASH_SOURCE[0]}"
    _lab_shell=bash
else
    _lab_env_file="$0"   # zsh
    _lab_shell=zsh
fi
LAB_ROOT="$(cd "$(dirname "$_lab_env_file")/.." && pwd)"
export LAB_ROOT
unset _lab_env_file

_lab_user_master="${ROS_MASTER_URI:-}"
_lab_user_hostname="${ROS_HOSTNAME:-}"
_lab_user_ip="${ROS_IP:-}"

_lab_devel="$LAB_ROOT/catkin_ws/devel"
if [ -f "$_lab_devel/setup.$_lab_shell" ]; then
    source "$_lab_devel/setup.$_lab_shell"
else
    echo "scripts/env.sh: the workspace is not built yet; run scripts/setup first." >&2
fi

# The student's workspace, on top of the lab's.
_lab_student_ws="${LAB_STUDENT_WS:-${HOME:+$HOME/catkin_ws}}"
_lab_student_src=""
if [ -n "$_lab_student_ws" ] && [ "$_lab_student_ws" != off ] && [ -f "$_lab_devel/setup.sh" ]; then
    _lab_student_src="$_lab_student_ws/src"
    if [ ! -e "$_lab_student_ws" ]; then
        if _lab_out="$(mkdir -p "$_lab_student_ws/src" && catkin_init_workspace "$_lab_student_ws/src" 2>&1 \
            && catkin config --init --workspace "$_lab_student_ws" --extend "$_lab_devel" \
                --cmake-args -DPYTHON_EXECUTABLE="$LAB_ROOT/.venv/bin/python3" 2>&1)"; then
            echo "scripts/env.sh: created your catkin workspace $_lab_student_ws: your packages go in its src" \
                "folder; build with catkin build (or catkin_make) there. LAB_STUDENT_WS=off opts out." >&2
        else
            echo "scripts/env.sh: could not create your catkin workspace $_lab_student_ws:" >&2
            echo "$_lab_out" | tail -n 5 >&2
        fi
    fi
    if [ -f "$_lab_student_ws/devel/setup.$_lab_shell" ]; then
        source "$_lab_student_ws/devel/setup.$_lab_shell"
        case ":$ROS_PACKAGE_PATH:" in
            *":$LAB_ROOT/catkin_ws/src:"*) ;;
            *)
                echo "scripts/env.sh: $_lab_student_ws was built without the lab underneath, so it would hide" \
                    "the lab's packages; left out. Rebuild it in this terminal: cd $_lab_student_ws &&" \
                    "catkin clean -y && catkin build (catkin_make: rm -r build devel && catkin_make)" >&2
                source "$_lab_devel/setup.$_lab_shell"
                ;;
        esac
    elif [ -d "$_lab_student_ws/src" ]; then
        # Not built yet: its source folder first on the package path all the same, as the course's machines have
        # it, so a package created there is found at once, before the lab's package of the same name.
        export ROS_PACKAGE_PATH="$_lab_student_ws/src${ROS_PACKAGE_PATH:+:$ROS_PACKAGE_PATH}"
        # And first on CMAKE_PREFIX_PATH as a source-only catkin workspace (a marker folder whose .catkin names that
        # src): rosrun and roslaunch look for a package's executables in the first workspace that has the package
        # (catkin_find), which was the lab's devel space with its relays of the reference package of the same name,
        # so `rosrun week4_services move_client.py` offered a "non-unique executable" menu (or roslaunch ran the
        # lab's node). Sourcing any devel/setup.bash, the student's after the first build too, takes it out again.
        _lab_marker="$_lab_student_ws/.lab_source_space"
        if { mkdir -p "$_lab_marker" && printf '%s' "$_lab_student_ws/src" > "$_lab_marker/.catkin"; } 2>/dev/null; then
            export CMAKE_PREFIX_PATH="$_lab_marker${CMAKE_PREFIX_PATH:+:$CMAKE_PREFIX_PATH}"
        fi
        unset _lab_marker
    fi
    # rospack reads the package folders at every call instead of trusting its cache for 60 s: a package created a
    # moment ago (or removed) is found at once (about 10 ms of CPU per call).
    export ROS_CACHE_TIMEOUT="${ROS_CACHE_TIMEOUT:-0}"
fi
unset _lab_student_ws _lab_out

# The venv first, and only once, wherever it was before: its python3 is Debian's interpreter with Box2D and
# pytest added.
_lab_venv_bin="$LAB_ROOT/.venv/bin"
_lab_rest="$PATH:"
_lab_path=""
while [ -n "$_lab_rest" ]; do
    _lab_entry="${_lab_rest%%:*}"
    _lab_rest="${_lab_rest#*:}"
    [ "$_lab_entry" = "$_lab_venv_bin" ] || _lab_path="$_lab_path:$_lab_entry"
done
export PATH="$_lab_venv_bin$_lab_path"
export VIRTUAL_ENV="$LAB_ROOT/.venv"
hash -r 2>/dev/null
unset _lab_venv_bin _lab_rest _lab_path _lab_entry

# rosbash's functions and completions (Debian installs them as a bash completion file that nothing sources).
if [ "$_lab_shell" = bash ]; then
    case "$-" in
        *i*)
            if [ -z "${BASH_COMPLETION_VERSINFO:-}" ] && [ -f /usr/share/bash-completion/bash_completion ]; then
                source /usr/share/bash-completion/bash_completion
            fi
            ;;
    esac
    if [ -f /usr/share/bash-completion/completions/rosbash ]; then
        source /usr/share/bash-completion/completions/rosbash
        # rosbash's roscd, rosls, rosed... and their Tab completion call rospack with ROS_CACHE_TIMEOUT=-1.0 (its
        # cache for ever): a package created in a terminal's lifetime stayed unknown there, or worse, roscd went to
        # the lab's package of the same name. In this shell rospack reads the package folders at every call.
        rospack() { ROS_CACHE_TIMEOUT=0 command rospack "$@"; }
        if [ -n "${_lab_student_src:-}" ]; then
            # roscd and rosed say so when they take you into one of the lab's reference packages (the exercises'
            # model answers), which happens only while your workspace has no package of that name: a file created
            # or changed there would be the lab's, not yours. (Read-only sources would not stop root, a container's
            # usual user, and would break git pull.)
            eval "_lab_rosbash_roscd() $(declare -f roscd | tail -n +2)"
            eval "_lab_rosbash_rosed() $(declare -f rosed | tail -n +2)"
            roscd() { _lab_rosbash_roscd "$@" && _lab_reference_note "$PWD"; }
            rosed() { _lab_reference_note "$(rospack find "${1:-}" 2>/dev/null)"; _lab_rosbash_rosed "$@"; }
        fi
    fi
fi

# One line when $1 is inside one of the lab's reference packages (see roscd above).
_lab_reference_note() {
    local inside="${1#"$LAB_ROOT/catkin_ws/src/exercises/"}"
    [ -n "${1:-}" ] && [ "$inside" != "$1" ] && [ -n "$inside" ] || return 0
    echo "note: $1 is the lab's reference package ${inside%%/*} (a model answer), not yours: what you create or" \
        "change here is the lab's. Your own goes in $_lab_student_src (catkin_create_pkg" \
        "${inside%%/*} ...); once it exists, roscd and rosrun find yours first." >&2
}

if [ -z "$_lab_user_master$_lab_user_hostname$_lab_user_ip" ]; then
    export ROS_HOSTNAME=localhost
    export ROS_MASTER_URI=http://localhost:11311
else
    [ -n "$_lab_user_master" ] && export ROS_MASTER_URI="$_lab_user_master"
fi
unset _lab_user_master _lab_user_hostname _lab_user_ip

# rospy's inbound TCPROS handshakes get a timeout in every Python process started from here (nodes, rosrun,
# roslaunch, the grader's sandbox): the lab's one patch of ROS behaviour, see rospy_handshake_timeout. Its
# sitecustomize folder goes first on PYTHONPATH.
_lab_startup="$LAB_ROOT/catkin_ws/src/lib/rospy_handshake_timeout/startup"
case ":${PYTHONPATH:-}:" in
    *":$_lab_startup:"*) ;;
    *) export PYTHONPATH="$_lab_startup${PYTHONPATH:+:$PYTHONPATH}" ;;
esac
unset _lab_startup

_lab_loopback="$_lab_devel/lib/libros_loopback.so"
if [ -f "$_lab_loopback" ]; then
    case ":${LD_PRELOAD:-}:" in
        *":$_lab_loopback:"*) ;;
        *) export LD_PRELOAD="$_lab_loopback${LD_PRELOAD:+:$LD_PRELOAD}" ;;
    esac
fi
unset _lab_loopback _lab_devel _lab_shell

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
