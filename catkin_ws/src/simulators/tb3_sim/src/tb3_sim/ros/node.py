"""The ROS 1 node around the simulation core: Gazebo's TurtleBot3 topics, /clock and /gazebo/* services.

Node name `gazebo` (as gzserver's), so its private services are /gazebo/reset_world and so on.

Robots: the node starts with one TurtleBot3 (~model, at ~x_pos, ~y_pos, ~yaw) unless ~spawn_robot is false, as
gazebo_ros's empty world; more come through /gazebo/spawn_urdf_model (or spawn_sdf_model) with a TurtleBot3 URDF
(robot name turtlebot3_burger, turtlebot3_waffle or turtlebot3_waffle_pi, as `spawn_model -urdf -param
robot_description` sends it), each in the request's robot_namespace with its frames prefixed (see
robot_naming): any number of robots, colliding with and seen by each other. Two robots may not share a namespace
(their topics would clash); a robot cannot be deleted.

Per robot (names below in its namespace):
Subscribes: `cmd_vel` (geometry_msgs/Twist, queue 1; linear.x and angular.z held until the next message, no
  timeout; NaN, inf or absurd values are ignored with a throttled warning and the previous command is kept).
Publishes: `odom` (nav_msgs/Odometry), /tf odom -> base_footprint and `joint_states` at 30 Hz; `scan`
  (sensor_msgs/LaserScan) at 5 Hz; `imu` (sensor_msgs/Imu) at 100 Hz (the last two only while subscribed); the
  camera's `camera/rgb/image_raw`, `camera/rgb/image_raw/compressed`, `camera/rgb/camera_info` and on a Waffle
  `camera/depth/image_raw` and `camera/depth/camera_info` at the camera's rate (30 Hz, only while subscribed; see
  outputs.camera); its fixed joints on /tf_static (latched) unless ~publish_static_tf is false.
Once: /clock at ~clock_rate (100 Hz of sim time; 0: every 5 ms physics step, see outputs.clock);
  /gazebo/model_states at 100 Hz while subscribed;
  /gazebo/set_model_state (subscribed, gazebo_msgs/ModelState); ~world_markers (visualization_msgs/MarkerArray,
  latched, and again at 2 Hz while subscribed: walls, models, the robots' bodies, for rviz/tb3_sim.rviz). All
  rates are in simulated time; each periodic output is one object registered in tb3_sim.ros.outputs.registry.
Services: /gazebo/{reset_world, reset_simulation, pause_physics, unpause_physics, spawn_sdf_model,
  spawn_urdf_model, delete_model, get_model_state, set_model_state, get_world_properties,
  get_physics_properties, set_physics_properties} (see gazebo_api),
  and ~snapshot (std_srvs/Empty): write a top-down PNG of the world (walls, models, robot, its trail, the
  latest laser rays; see renderer) to ~snapshot_path; an unwritable path fails the call with the reason.
Parameters: see tb3_sim.ros.config (~world, ~spawn_robot, ~model, ~x_pos, ~y_pos, ~yaw, ~robot_name, ~seed,
  ~real_time_factor, ~clock_rate, ~lidar_sees_low_objects, ~clamp_command, ~paused, ~headless, ~snapshot_path,
  ~publish_static_tf, ~camera_width, ~camera_height, ~camera_rate, ~ground_truth_socket).
Ground truth: with ~ground_truth_socket, the robot's true motion, every world change made through the /gazebo
  services and a reset go to a trusted client over a private Unix socket (see ground_truth): the grader's
  channel, which no ROS node can publish on, pause or intercept.
/use_sim_time is set to true before the node starts if it is absent, as gazebo_ros does. If roscore is
restarted, the node registers everything again with the new master and sets /use_sim_time there too
(master_reconnect). When the node exits (Ctrl-C, the launch ending, a bad parameter), it puts /use_sim_time back
as it was before: as ~use_sim_time_before says (true, false or unset: tb3_sim.launch records what it found), else
as the node found it; a roscore that outlives the simulator then serves wall-clock nodes again (sim_clock).
View: when $DISPLAY (or $WAYLAND_DISPLAY) is set and ~headless is false, a top-down window (see window) shows
the world and offers the Gazebo box tool; physics then runs in a second thread while Qt owns the main thread.
Closing the window leaves the simulation running headless, as closing gzclient leaves gzserver; Ctrl-C stops
both. Without a display the node is headless with identical ROS behaviour.

Differences from Gazebo, on purpose:
- Physics is 2D (Box2D) with 5 ms steps: objects stand on the floor, z, roll and pitch are always 0, spawned
  models are single boxes, cylinders or spheres; physics steps 5 ms instead of 1 ms, and /clock goes out at
  ~clock_rate (100 Hz) instead of after every step (gazebo_ros's pub_clock_frequency).
- /imu and /gazebo/model_states go out at 100 Hz instead of on every 1 ms world update.
- /tf_static carries each robot's fixed joints (robot_state_publisher's job in Gazebo launches, which may run
  beside it: both publish the same transforms) unless ~publish_static_tf is false; the IMU message is in
  base_footprint, as Gazebo's URDF conversion leaves it.
- The camera renders the 2D world in 2.5D (upright solids of each object's height and colour, a flat floor or
  the world's floor layer in perspective, a sky; no wall textures, lights or shadows); /camera/depth/points is
  not published; camera_info is published to a camera_info subscriber even when no image is taken.
- set_model_state composes the pose with its reference frame (Gazebo has a known bug there); spawn and delete
  take effect within the call instead of after up to 10 s or 60 s.

Threads: the main thread (with a window: a "physics" thread) steps physics and publishes; rospy runs every
callback in its own thread. One lock guards the world: callbacks change it only between two steps. Publishers
write synchronously from the loop thread, except the latched ones and the camera images, which rospy's writer
threads send (see publishers).

Time: physics runs in simulated time and every stamp is the world's time. The node is the clock, so it does not
subscribe to its own /clock (rospy's `disable_rostime`: at 200 Hz x the real-time factor that echo would cost a
third of the loop); its rospy time, used only for log stamps and warning throttles, is therefore wall time, and
so is the pacing of steps (`~real_time_factor`), which waits only after steps that sent /clock (see
ClockOutput.ticked).
"""

import sys
import threading
import time
from contextlib import contextmanager
from pathlib import Path

import rosgraph
import rospkg
import rospy
from geometry_msgs.msg import Twist
from std_srvs.srv import Empty, EmptyResponse
from tf2_msgs.msg import TFMessage
from window_hint import can_open_window

from master_reconnect import keep_registered
from sim_clock import read_state, restore_state
from stop_request import StopRequest
from stop_request.closed_topic import shutting_down
from tb3_sim.core.diff_drive import validate_command
from tb3_sim.core.errors import BadRequestError, SimError
from tb3_sim.core.geometry import Pose2D
from tb3_sim.core.pacing import Pacer
from tb3_sim.core.physics_properties import PhysicsProperties
from tb3_sim.core.schedule import PeriodicSchedule
from tb3_sim.core.turtlebot3 import TURTLEBOT3_MODELS
from tb3_sim.core.world import World
from tb3_sim.core.world_file import load_world
from tb3_sim.ros import messages
from tb3_sim.ros.config import config_from_params
from tb3_sim.ros.gazebo_api import GazeboApi
from tb3_sim.ros.ground_truth import GroundTruthChannel
from tb3_sim.ros.outputs import OutputPublisher, robot_outputs, world_outputs
from tb3_sim.ros.outputs.camera import FloorTextures
from tb3_sim.ros.outputs.clock import ClockOutput
from tb3_sim.ros.outputs.scan import ScanOutput
from tb3_sim.ros.publishers import output_publisher
from tb3_sim.ros.robot_naming import spawned_robot_naming
from tb3_sim.view.scene import Trails, scene_of

NODE_NAME = "gazebo"
PACKAGE = "tb3_sim"
USE_SIM_TIME_PARAM = "/use_sim_time"
USE_SIM_TIME_BEFORE_PARAM = "~use_sim_time_before"
WARNING_THROTTLE_S = 5.0
PAUSED_POLL_S = 0.05
MASTER_RETRY_S = 1.0
TRAIL_RATE_HZ = 30.0
SHUTDOWN_CHECK_MS = 100


class SimNode:
    """Owns the world, the lock around it, the pause flag, the robots' ROS ends and the publishing loop (`spin`)."""

    def __init__(self, config, world):
        self.config = config
        self._world = world
        self._lock = threading.Lock()
        self._window_open = threading.Event()
        self._running = threading.Event()
        if not config.paused:
            self._running.set()
        self._physics = PhysicsProperties.for_pacing(world.step_s, config.real_time_factor)
        self._pacer = Pacer(config.real_time_factor)
        self._outputs = OutputPublisher(world_outputs(config), output_publisher)
        self._floor_textures = FloorTextures()
        self._floor_textures.prepare(world.description.floor)   # at world load, not at the first camera image
        self._clock = self._outputs.output(ClockOutput)
        self._namings = {}        # robot name -> RobotNaming
        self._cmd_vel = []        # one Subscriber per robot
        self._static_transforms = ()
        self._static_tf = None
        self._truth = None        # the GroundTruthChannel when ~ground_truth_socket is set
        if config.publish_static_tf:
            self._static_tf = rospy.Publisher("/tf_static", TFMessage, queue_size=1, latch=True)
        self._trails = Trails()
        self._trail_schedule = PeriodicSchedule(TRAIL_RATE_HZ)
        for robot in world.robots():
            self._attach(robot, spawned_robot_naming(rospy.get_namespace(), _tf_prefix_param(rospy.get_namespace())))
        self._services = GazeboApi(self).advertise()
        self._snapshot = rospy.Service("~snapshot", Empty, self._on_snapshot)
        for publisher, message in self._outputs.latched(world):
            publisher.publish(message)
        if config.ground_truth_socket:
            self._truth = GroundTruthChannel(config.ground_truth_socket, self, {
                "node": rospy.get_name(), "uri": rospy.get_node_uri(), "robot": config.robot_name})

    def spawn_robot(self, name, model, pose, robot_namespace):
        """Add a TurtleBot3 of `model` named `name` at `pose` (world) with its topics in `robot_namespace`.

        Raises SimError: DuplicateModelError, OverlapError, or BadRequestError if another robot has that namespace.
        """
        naming = spawned_robot_naming(robot_namespace, _tf_prefix_param(robot_namespace))
        with self._lock:
            for other, other_naming in self._namings.items():
                if other_naming.namespace == naming.namespace:
                    raise BadRequestError(
                        f"robot namespace '{naming.namespace}' is already used by robot '{other}', so their topics "
                        f"would clash: spawn it in another namespace (spawn_model in a <group ns=...>, or "
                        f"-robot_namespace)")
            self._attach(self._world.add_robot(name, model, pose), naming)

    def _attach(self, robot, naming):
        """Give `robot` its ROS ends: outputs, cmd_vel and static transforms (world locked, or not yet shared)."""
        self._namings[robot.name] = naming
        self._outputs.add(robot_outputs(self.config, robot, naming, len(self._namings) - 1, self._floor_textures),
                          self._world.time_s)
        self._cmd_vel.append(rospy.Subscriber(naming.topic("cmd_vel"), Twist, self._on_cmd_vel, callback_args=robot,
                                              queue_size=1))
        if self._static_tf is not None:
            self._static_transforms += naming.transforms(robot.model.static_transforms)
            self._static_tf.publish(messages.static_tf_message(self._world.time_s, self._static_transforms))

    @property
    def _scan(self):
        """The first robot's ScanOutput (the one a view shows), or None without robots."""
        return self._outputs.output(ScanOutput)

    @contextmanager
    def locked_world(self):
        """The world, for use between two physics steps (hold it briefly: physics waits)."""
        with self._lock:
            yield self._world

    @property
    def rendering_enabled(self):
        """True while a window draws the world (get_world_properties); headless runs answer False."""
        return self._window_open.is_set()

    def scene(self):
        """A Scene of the world now, with the latest published scan (for a window: no extra LiDAR sweeps)."""
        with self._lock:
            scan = self._scan.recent(self._world.time_s) if self._scan else None
            return scene_of(self._world, self._trails, scan)

    @property
    def paused(self):
        return not self._running.is_set()

    @property
    def physics_properties(self):
        """The PhysicsProperties last set (at start: the physics step and ~real_time_factor)."""
        return self._physics

    def set_physics_properties(self, properties):
        """Pace the simulation at `properties.real_time_factor` from now on."""
        self._physics = properties
        self._pacer = Pacer(properties.real_time_factor)

    def pause(self):
        self._running.clear()

    def unpause(self):
        self._running.set()

    def reset_world(self):
        """Models and robot back to their initial poses, command zeroed; sim time keeps running."""
        with self._lock:
            self._world.reset_world()
            self._outputs.forget_motion()
            self._trails.clear()

    def reset_simulation(self):
        """reset_world plus sim time back to 0 (/clock jumps back, as Gazebo's does)."""
        with self._lock:
            self._world.reset_simulation()
            self._outputs.reset(self._world.time_s)
            self._trail_schedule.reset(self._world.time_s)
            if self._truth is not None:
                self._truth.clock_jumped(self._world.time_s)
            self._trails.clear()

    def window_opened(self):
        self._window_open.set()

    def window_closed(self):
        self._window_open.clear()
        rospy.loginfo("tb3_sim: window closed; the simulation keeps running headless (Ctrl-C stops it)")

    def teleported(self):
        """Tell the sensors a model was moved by a service (call with the world locked)."""
        self._outputs.forget_motion()

    def world_changed(self, what, detail=""):
        """Report a world change a ROS client made (a /gazebo service: `what` is its name) on the ground-truth
        channel, if one is served."""
        if self._truth is not None:
            self._truth.event(what, detail, self._world.time_s)

    def _on_cmd_vel(self, message, robot):
        linear, angular = message.linear.x, message.angular.z
        reason = validate_command(linear, angular)
        if reason is not None:
            rospy.logwarn_throttle(WARNING_THROTTLE_S, f"cmd_vel ignored: {reason}; keeping the previous command")
            return
        with self._lock:
            robot.set_command(linear, angular)

    def _on_snapshot(self, _request):
        from tb3_sim.view.renderer import save_png  # Qt is loaded on the first snapshot only (or by the window)
        with self._lock:
            scene = scene_of(self._world, self._trails, self._scan.for_view(self._world) if self._scan else None)
        try:
            save_png(scene, self.config.snapshot_path)
        except OSError as error:
            raise rospy.ServiceException(f"snapshot: {error}") from None
        rospy.loginfo(f"snapshot written to {self.config.snapshot_path}")
        return EmptyResponse()

    def spin(self, stop):
        """Step, publish and pace until ROS shuts down or `stop` (a StopRequest) is set."""
        while not (rospy.is_shutdown() or stop.is_set()):
            # is_set() first: Event.wait takes a lock even when set, a cost on every step when unpaced.
            if not self._running.is_set() and not self._running.wait(PAUSED_POLL_S):
                self._pacer.restart(self._world.time_s, time.monotonic())
                if self._truth is not None:
                    with self._lock:
                        self._truth.heartbeat(self._world)
                continue
            with self._lock:
                now_s = self._world.step()
                outgoing = self._outputs.collect(self._world)
                if self._trail_schedule.due(now_s):
                    self._trails.add(self._world.robots())
                if self._truth is not None:
                    self._truth.after_step(self._world, now_s)
            try:
                for publisher, message in outgoing:
                    publisher.publish(message)
            except rospy.ROSException:
                if shutting_down():
                    return   # Ctrl-C closed the publishers after the loop's shutdown check
                raise
            if self._clock.ticked(now_s):
                self._wait_for_pace(now_s, stop)

    def _wait_for_pace(self, sim_s, stop):
        """Sleep until the pacer lets `sim_s` go out, in waits of at most the pacer's max_sleep_s, so a stop
        request or a new pacing (set_physics_properties) is seen within that time."""
        while not rospy.is_shutdown():
            delay_s = self._pacer.delay(sim_s, time.monotonic())
            if not delay_s or stop.wait(delay_s):
                return


def run_with_window(node, stop):
    """Show the window in the main thread (Qt's rule) and step physics in another until ROS shuts down or `stop`
    is set."""
    from PyQt5.QtCore import QTimer
    from PyQt5.QtWidgets import QApplication

    from tb3_sim.view.box_tool import BoxTool
    from tb3_sim.view.window import SimWindow

    app = QApplication.instance() or QApplication([sys.argv[0]])
    window = SimWindow(node.scene, BoxTool(node), on_close=node.window_closed, log=rospy.loginfo)
    physics = threading.Thread(target=node.spin, args=(stop,), name="physics", daemon=True)
    shutdown_check = QTimer()
    shutdown_check.timeout.connect(lambda: (rospy.is_shutdown() or stop.is_set()) and app.quit())
    shutdown_check.start(SHUTDOWN_CHECK_MS)
    node.window_opened()
    window.show()
    physics.start()
    app.exec_()
    while physics.is_alive():
        physics.join(PAUSED_POLL_S)


def window_possible(config):
    """True when the window should open: not ~headless and a display to open it on. Without one (and not chosen
    headless), one line says how to see the world here instead of the window the course's Gazebo would show."""
    return not config.headless and can_open_window(
        "tb3_sim", "roslaunch turtlebot3_gazebo <world>.launch", rospy.loginfo, rospy.logwarn)


def worlds_dir():
    """The shipped worlds folder of the tb3_sim package, found through the ROS package path."""
    return Path(rospkg.RosPack().get_path(PACKAGE)) / "worlds"


def ensure_use_sim_time():
    """Set /use_sim_time to true on the master if no one has set it (launch files set it themselves); returns
    the state found (sim_clock.read_state: 'true', 'false' or 'unset').

    Waits for the master like rospy.init_node does, so `rosrun` before `roscore` just waits.
    """
    master = rosgraph.Master(NODE_NAME)
    waiting = False
    while True:
        try:
            found = read_state(master)
            if not master.hasParam(USE_SIM_TIME_PARAM):
                master.setParam(USE_SIM_TIME_PARAM, True)
            return found
        except OSError:
            if not waiting:
                print(f"tb3_sim: waiting for the ROS master at {rosgraph.get_master_uri()}", file=sys.stderr)
                waiting = True
            time.sleep(MASTER_RETRY_S)


def build_world(config):
    """The World the config describes; raises SimError (WorldFileError, ConfigError...) with a clear message."""
    description = load_world(config.world_path)
    return World(description, Pose2D(config.x_pos, config.y_pos, config.yaw),
                 config.robot_name if config.spawn_robot else None, TURTLEBOT3_MODELS[config.model],
                 clamp_command=config.clamp_command)


def _tf_prefix_param(namespace):
    """The tf_prefix parameter found by searching up from `namespace` (as gazebo_ros's plugins look it up), or
    None if there is none."""
    master = rosgraph.Master(rospy.names.ns_join(namespace or "/", NODE_NAME))
    try:
        return master.getParam(master.searchParam("tf_prefix"))
    except (rosgraph.MasterException, OSError):
        return None


def put_back_use_sim_time(state):
    """Restore /use_sim_time to `state` on exit, and drop ~use_sim_time_before, which would be stale for a later
    node of this name; a master already gone took both parameters with it."""
    try:
        master = rosgraph.Master(NODE_NAME)
        recorded = rospy.resolve_name(USE_SIM_TIME_BEFORE_PARAM)
        if master.hasParam(recorded):
            master.deleteParam(recorded)
        restore_state(master, state)
    except ValueError as error:
        rospy.logwarn(f"tb3_sim: /use_sim_time left as it is: ~use_sim_time_before: {error}")
    except (OSError, rosgraph.MasterException):
        pass


def main():
    """Entry point of `rosrun tb3_sim tb3_sim_node`; exits 1 with a one-line reason on bad parameters."""
    use_sim_time_before = None
    try:
        use_sim_time_found = ensure_use_sim_time()
        rospy.init_node(NODE_NAME, disable_rostime=True, disable_signals=True)
        use_sim_time_before = rospy.get_param(USE_SIM_TIME_BEFORE_PARAM, use_sim_time_found)
        stop = StopRequest()
        stop.install()
        try:
            config = config_from_params(rospy.get_param("~", {}), worlds_dir())
            world = build_world(config)
        except SimError as error:
            rospy.logfatal(f"tb3_sim: {error}")
            sys.exit(1)
        node = SimNode(config, world)
        keep_registered(on_reregistered=ensure_use_sim_time)
        robot = (f"robot '{config.robot_name}' ({config.model}) at ({config.x_pos}, {config.y_pos}, yaw {config.yaw})"
                 if config.spawn_robot else "no robot (spawn one with spawn_model -urdf)")
        rospy.loginfo(f"tb3_sim: world '{world.description.name}', {robot}, real_time_factor "
                      f"{config.real_time_factor:g}{', paused' if config.paused else ''}")
        if window_possible(config):
            run_with_window(node, stop)
        else:
            node.spin(stop)
    except (KeyboardInterrupt, rospy.ROSInterruptException):
        pass
    finally:
        if use_sim_time_before is not None:
            put_back_use_sim_time(use_sim_time_before)
    rospy.signal_shutdown("tb3_sim stopping")
