"""move_base (imports rospy): the move_base action over two costmaps, navfn and DWA, as the original runs it.

Node type move_base, default name `move_base_node` (launch files name it move_base); private topics and
services under the node's name, the action always at `move_base`. Start-up in the original's order: the global
costmap (waits for TF map -> base frame, then for /map), the local costmap, the planners, and the action
server last, so wait_for_server() returns once a map and a localisation exist.

A goal (action or /move_base_simple/goal, which is re-sent on move_base/goal with an empty id) is checked
(an invalid quaternion aborts it at once), transformed into the global frame (until that succeeds it stays
active and the robot stands still, with a warning each cycle), then planned at planner_frequency and followed at
controller_frequency by lab_nav's MoveBaseLogic: succeeded with "Goal reached.", aborted with the original's
texts after the recoveries, preempted by a new goal or a cancel (the robot stops on cancel). A zero Twist is
sent on goal start, success, abort, cancel and each recovery, and on shutdown.

The periodic work runs in sim time from one thread (lab_nav's PeriodicTasks): both costmaps' updates and
publishing, and the control tick that wakes the action's goal thread for its next cycle. Under /use_sim_time
every thread sleeping in rospy wakes at each /clock message (100 per sim second) to look at the time; with the
five timers and rates this replaces, the /clock callback's notify alone took 12 % of move_base's busy samples
(py-spy --gil at factor 10), 4 % with one sleeper. That thread sleeps on nav_ros.sim_clock's alarm, which wakes it
only when a task is due (about 20 times a sim second, not 100).
"""
import threading

import actionlib
import numpy as np
import rospy
import tf2_ros
from geometry_msgs.msg import PoseStamped, Twist
from move_base_msgs.msg import MoveBaseAction, MoveBaseActionGoal, MoveBaseFeedback, MoveBaseResult, RecoveryStatus
from nav_msgs.msg import Odometry, Path
from nav_msgs.srv import GetPlan, GetPlanResponse
from nav_ros import poses
from nav_ros.params import ParamError
from nav_ros.sim_clock import PeriodicThread
from std_srvs.srv import Empty, EmptyResponse

from lab_nav.planning.goal import INVALID_QUATERNION_ABORT, quaternion_problem
from lab_nav.planning.local_planner import DwaPlanner
from lab_nav.planning.move_base_logic import CLEARING, CONTROLLING, MoveBaseLogic
from lab_nav.planning.periodic import PeriodicTasks
from lab_nav.planning.recovery import CLEARABLE_LAYERS, RotateParams, RotateRecovery
from sim_clock import quiet_time_notifications
from stop_request.closed_topic import publish_unless_shut_down

from .config import read_costmap, read_dwa, read_move_base
from .costmap_ros import CostmapRos
from .planners_ros import DwaRos, NavfnRos, path_message

NODE_NAME = "move_base_node"
INACTIVE_ONLY = "move_base must be in an inactive state to make a plan for an external user"
TF_ERRORS = (tf2_ros.LookupException, tf2_ros.ConnectivityException, tf2_ros.ExtrapolationException,
             tf2_ros.TimeoutException)
ROTATE_CHECK_RAD = 1.0
TICK_WAIT_S = 1.0
"""Wall seconds the goal thread waits for a control tick before it looks again whether ROS is shutting down (no
tick comes while the simulation is paused)."""


class MoveBaseNode:
    def __init__(self):
        self.params = read_move_base()
        self.dwa_params = read_dwa(self.params.controller_frequency)
        self.tf = tf2_ros.Buffer()
        self._tf_listener = tf2_ros.TransformListener(self.tf)
        self.global_costmap = CostmapRos(read_costmap("global_costmap", False), self.tf)
        self.local_costmap = CostmapRos(read_costmap("local_costmap", False), self.tf)
        self.logic = MoveBaseLogic(self.params)
        self._velocity = (0.0, 0.0)
        self._cmd_pub = rospy.Publisher("cmd_vel", Twist, queue_size=1)
        self._current_goal_pub = rospy.Publisher("~current_goal", PoseStamped, queue_size=1)
        self._recovery_pub = rospy.Publisher("~recovery_status", RecoveryStatus, queue_size=1)
        self._action_goal_pub = rospy.Publisher("move_base/goal", MoveBaseActionGoal, queue_size=1)
        self.server = actionlib.SimpleActionServer("move_base", MoveBaseAction, execute_cb=self.execute,
                                                   auto_start=False)
        self._plan_lock = threading.Lock()
        self._tasks = PeriodicTasks()
        self._tick = threading.Condition()
        self._ticks = 0

    def start(self):
        if not (self.global_costmap.start() and self.local_costmap.start()):
            return False
        self.navfn = NavfnRos(self.global_costmap)
        self.dwa = DwaPlanner(self.dwa_params, self.local_costmap.config.params.footprint)
        self.dwa_ros = DwaRos()
        rospy.loginfo("Sim period is set to %.2f", self.dwa_params.sim_period)
        rospy.Subscriber("odom", Odometry, self._on_odom, queue_size=1)
        rospy.Subscriber("move_base_simple/goal", PoseStamped, self._on_simple_goal, queue_size=1)
        rospy.Service("~make_plan", GetPlan, self._on_make_plan)
        rospy.Service("~NavfnROS/make_plan", GetPlan, self._on_navfn_make_plan)
        rospy.Service("~clear_costmaps", Empty, self._on_clear_costmaps)
        self._tasks.add(1.0 / self.params.controller_frequency, self._control_tick)   # first: see _control_tick
        for costmap in (self.global_costmap, self.local_costmap):
            costmap.schedule(self._tasks)
        self.server.start()
        self._schedule_action_status()
        PeriodicThread(self._tasks, "move_base_periodic")
        return True

    # --- the periodic thread ------------------------------------------------------------------------------
    def _schedule_action_status(self):
        """Publish the action's status (move_base/status) from the periodic thread instead of actionlib's own
        rospy.Timer, at the same actionlib_status_frequency (5 Hz) in sim time: that timer's thread, sleeping in
        rospy, woke at every /clock message. Uses actionlib's ActionServer.status_timer and
        publish_status_async (actionlib 1.14; the timer exists once the server has started); if a version lacks
        them its timer is left as it is."""
        action_server = self.server.action_server
        timer = getattr(action_server, "status_timer", None)
        publish = getattr(action_server, "publish_status_async", None)
        if timer is None or publish is None or not action_server.status_frequency > 0.0:
            return
        timer.shutdown()
        self._tasks.add(1.0 / action_server.status_frequency, lambda: publish(None), first_after_period=True)

    def _control_tick(self):
        """Wake the goal thread for a control cycle. It runs before the costmaps' updates, so the cycle computes
        while this thread updates (the local costmap's lock orders the two), as move_base's controller thread does
        beside its costmap threads: after them, a slow global update (a map-wide change) delayed the command."""
        with self._tick:
            self._ticks += 1
            self._tick.notify_all()

    def _wait_tick(self):
        """Wait for the next control tick (controller_frequency in sim time); False once ROS shuts down."""
        with self._tick:
            seen = self._ticks
            while self._ticks == seen:
                if rospy.is_shutdown():
                    return False
                self._tick.wait(TICK_WAIT_S)
        return True

    # --- inputs -------------------------------------------------------------------------------------------
    def _on_odom(self, odom):
        self._velocity = (odom.twist.twist.linear.x, odom.twist.twist.angular.z)

    def _on_simple_goal(self, pose_stamped):
        rospy.logdebug("In ROS goal callback, wrapping the PoseStamped in the action message and re-sending to the "
                       "server.")
        action_goal = MoveBaseActionGoal()
        action_goal.header.stamp = rospy.Time.now()
        action_goal.goal.target_pose = pose_stamped
        publish_unless_shut_down(self._action_goal_pub.publish, action_goal)

    def _on_clear_costmaps(self, _request):
        self.global_costmap.reset()
        self.local_costmap.reset()
        return EmptyResponse()

    def _to_frame(self, pose_stamped, frame):
        """(x, y, yaw) of a PoseStamped in `frame`; None (with the original's warning) without TF."""
        source = pose_stamped.header.frame_id.lstrip("/")
        try:
            transform = self.tf.lookup_transform(frame, source, rospy.Time(0), rospy.Duration(0.1))
        except TF_ERRORS as error:
            rospy.logwarn("Failed to transform the goal pose from %s into the %s frame: %s", source, frame, error)
            return None
        return poses.compose(poses.from_transform(transform), poses.from_pose(pose_stamped.pose))

    # --- make_plan ----------------------------------------------------------------------------------------
    def _on_make_plan(self, request):
        if self.logic.active:
            raise rospy.ServiceException(INACTIVE_ONLY)
        return self._on_navfn_make_plan(request)

    def _on_navfn_make_plan(self, request):
        frame = self.global_costmap.config.global_frame
        if request.start.header.frame_id == "":
            start = self.global_costmap.robot_pose()
        else:
            start = self._to_frame(request.start, frame)
        goal = self._to_frame(request.goal, frame)
        response = GetPlanResponse()
        response.plan = Path()
        response.plan.header.frame_id = frame
        if start is None or goal is None:
            return response
        with self._plan_lock:
            points = self.navfn.plan(start, goal, max(request.tolerance, self.navfn.default_tolerance))
        if points is None:
            return response
        if np.hypot(*(points[-1] - goal[:2])) > 1e-9:
            points = np.vstack((points, goal[:2]))
        response.plan = path_message(frame, rospy.Time.now(), points, goal)
        return response

    # --- the action ---------------------------------------------------------------------------------------
    def _stop(self):
        publish_unless_shut_down(self._cmd_pub.publish, Twist())

    def _accept(self, goal):
        q = goal.target_pose.pose.orientation
        problem = quaternion_problem(q.x, q.y, q.z, q.w)
        if problem is not None:
            rospy.logerr(problem)
            self._stop()
            self.logic.finish()
            self.server.set_aborted(MoveBaseResult(), INVALID_QUATERNION_ABORT)
            return False
        self._goal = goal
        self._target = None
        self._plan = None
        self._stop()
        pose = self.global_costmap.robot_pose()
        self.logic.start(rospy.get_time(), pose[:2] if pose else (0.0, 0.0))
        return True

    def execute(self, goal):
        """The action server's goal thread; a topic closed by shutdown ends it quietly."""
        try:
            self._execute(goal)
        except rospy.ROSException:
            if not rospy.is_shutdown():
                raise

    def _execute(self, goal):
        if not self._accept(goal):
            return
        while not rospy.is_shutdown():
            if self.server.is_preempt_requested():
                if self.server.is_new_goal_available():
                    if not self._accept(self.server.accept_new_goal()):
                        return
                else:
                    self._stop()
                    self.logic.finish()
                    self.server.set_preempted()
                    return
            if self._cycle():
                return
            if not self._wait_tick():
                break
        self._stop()
        self.logic.finish()
        if self.server.is_active():
            self.server.set_aborted(MoveBaseResult(), "move_base is shutting down")

    def _cycle(self):
        """One control cycle; True when the goal has ended."""
        now = rospy.get_time()
        pose = self.global_costmap.robot_pose()
        if pose is None:
            self._stop()
            return False
        self._publish_feedback(pose)
        if self._target is None:
            self._target = self._to_frame(self._goal.target_pose, self.global_costmap.config.global_frame)
            if self._target is None:
                self.logic.start(now, pose[:2])
                return False
            current = PoseStamped()
            current.header.frame_id, current.header.stamp = self.global_costmap.config.global_frame, rospy.Time.now()
            current.pose = poses.to_pose(self._target)
            publish_unless_shut_down(self._current_goal_pub.publish, current)
        if self.logic.planner_due(now):
            with self._plan_lock:
                points = self.navfn.plan(pose, self._target)
            self.navfn.publish(points, self._target)
            if points is not None:
                self._plan = points
            if self.logic.on_plan(now, points is not None) is not None:
                self._stop()
        if self.logic.state == CONTROLLING:
            return self._control(now, pose)
        if self.logic.state == CLEARING:
            return self._recover(pose)
        return False

    def _publish_feedback(self, pose):
        feedback = MoveBaseFeedback()
        feedback.base_position.header.frame_id = self.global_costmap.config.global_frame
        feedback.base_position.header.stamp = rospy.Time.now()
        feedback.base_position.pose = poses.to_pose(pose)
        self.server.publish_feedback(feedback)

    def _local_plan(self, local_pose):
        """The global plan and goal in the local costmap's frame, from the point nearest the robot on."""
        local_frame = self.local_costmap.config.global_frame
        try:
            to_local = poses.from_transform(self.tf.lookup_transform(
                local_frame, self.global_costmap.config.global_frame, rospy.Time(0), rospy.Duration(0.1)))
        except TF_ERRORS:
            return None, None
        c, s = np.cos(to_local[2]), np.sin(to_local[2])
        plan = self._plan
        points = np.column_stack((to_local[0] + c * plan[:, 0] - s * plan[:, 1],
                                  to_local[1] + s * plan[:, 0] + c * plan[:, 1]))
        nearest = int(np.argmin(np.hypot(points[:, 0] - local_pose[0], points[:, 1] - local_pose[1])))
        return points[nearest:], poses.compose(to_local, self._target)

    def _control(self, now, pose):
        local_pose = self.local_costmap.robot_pose()
        plan, goal = self._local_plan(local_pose) if local_pose is not None else (None, None)
        if plan is None:
            self._stop()
            return False
        self.dwa.set_plan(plan, goal)
        with self.local_costmap.lock:
            command = self.dwa.compute(local_pose, self._velocity, self.local_costmap.costmap)
        self.dwa_ros.publish(self.local_costmap.config.global_frame, plan, command.trajectory)
        if not command.valid:
            rospy.logwarn("DWA planner failed to produce path.")
        outcome = self.logic.on_control(now, pose[:2], reached=command.reached, command_valid=command.valid)
        if outcome.kind == "drive":
            twist = Twist()
            twist.linear.x, twist.angular.z = command.v, command.w
            publish_unless_shut_down(self._cmd_pub.publish, twist)
            return False
        self._stop()
        if outcome.kind == "succeeded":
            rospy.loginfo("Goal reached")
            self.logic.finish()
            self.server.set_succeeded(MoveBaseResult(), outcome.text)
            return True
        return False

    # --- recoveries ---------------------------------------------------------------------------------------
    def _recover(self, pose):
        outcome = self.logic.next_recovery()
        self._stop()
        if outcome.kind == "aborted":
            rospy.logerr(outcome.log)
            self.logic.finish()
            self.server.set_aborted(MoveBaseResult(), outcome.text)
            return True
        recovery = outcome.recovery
        status = RecoveryStatus()
        status.pose_stamped.header.frame_id = self.global_costmap.config.global_frame
        status.pose_stamped.header.stamp = rospy.Time.now()
        status.pose_stamped.pose = poses.to_pose(pose)
        status.current_recovery_number = outcome.index
        status.total_number_of_recoveries = len(self.logic.recoveries)
        status.recovery_behavior_name = recovery.name
        publish_unless_shut_down(self._recovery_pub.publish, status)
        if recovery.rotates:
            if not self._rotate():
                return False
        else:
            rospy.logwarn(recovery.clear_message())
            for costmap in (self.global_costmap, self.local_costmap):
                costmap.clear_outside(recovery.reset_distance, CLEARABLE_LAYERS)
        after = self.global_costmap.robot_pose() or pose
        self.logic.end_recovery(rospy.get_time(), after[:2])
        return False

    def _rotate(self):
        """rotate_recovery: one full turn counter-clockwise; False when a goal change interrupted it."""
        rospy.logwarn("Rotate recovery behavior started.")
        params = RotateParams()
        pose = self.local_costmap.robot_pose()
        if pose is None:
            return True
        rotation = RotateRecovery(pose[2], params)
        rate = rospy.Rate(params.frequency)
        while not rospy.is_shutdown():
            if self.server.is_preempt_requested():
                return False
            pose = self.local_costmap.robot_pose()
            w = rotation.command(pose[2]) if pose is not None else None
            if w is None:
                break
            ahead = np.array([[[pose[0], pose[1], pose[2] + a] for a in np.linspace(0.0, ROTATE_CHECK_RAD, 11)]])
            with self.local_costmap.lock:
                costs, collides = self.dwa.footprint_costs(ahead, self.local_costmap.costmap)
            if collides.any():
                rospy.logerr("Rotate recovery can't rotate in place because there is a potential collision. "
                             "Cost: %.2f", float(costs.max()))
                break
            twist = Twist()
            twist.angular.z = w
            publish_unless_shut_down(self._cmd_pub.publish, twist)
            try:
                rate.sleep()
            except rospy.ROSInterruptException:
                break
        self._stop()
        return True


def main():
    quiet_time_notifications()
    rospy.init_node(NODE_NAME)
    try:
        node = MoveBaseNode()
    except ParamError as error:
        rospy.logfatal(str(error))
        return 1
    rospy.on_shutdown(node._stop)
    if not node.start():
        return 0
    rospy.spin()
    return 0
