"""move_group's execution: the move_action and execute_trajectory actions, run on the FollowJointTrajectory
controllers moveit_controllers.yaml (or a controller manager) names, or streamed to gz-sim
JointPositionController command topics."""

from __future__ import annotations

import math
import threading
import time
from typing import Any

import numpy as np
from control_msgs.action import FollowJointTrajectory
from moveit_msgs.action import ExecuteTrajectory, MoveGroup
from moveit_msgs.msg import (
    DisplayTrajectory,
)
from rclpy.action.client import ActionClient
from std_msgs.msg import Float64
from trajectory_msgs.msg import JointTrajectory, JointTrajectoryPoint

from ..planning import START_BOUNDS_ERROR, ArmPlanner, PlanningError, quoted
from ._move_group_base import (
    _ENDED,
    CONTROLLER_WAIT,
    GZ_CMD_POS,
    STREAM_GOAL_TOLERANCE,
    STREAM_RATE_HZ,
    Controller,
    _code,
    _seconds,
)
from ._move_group_planning import _Planning


class _Execution(_Planning):
    """The actions and the controllers they run on."""

    _stops = 0
    """How many "stop" events /trajectory_execution_event has brought: an execution that began before the
    latest one stops as a cancelled goal does."""

    def _on_execution_event(self, msg: Any) -> None:
        """MoveIt's ``TrajectoryExecutionManager::receiveEvent``/``processEvent``
        (trajectory_execution_manager.cpp, Jazzy): "stop" stops every execution in progress (its goal ends
        with PREEMPTED); any other event is a warning."""
        self.get_logger().info(f"Received event {quoted(msg.data)}")
        if msg.data == "stop":
            self._stops += 1
        else:
            self.get_logger().warning(f"Unknown event type: {quoted(msg.data)}")

    # ------------------------------------------------------------------ actions
    def _execute_move_group(self, handle: Any) -> MoveGroup.Result:
        """The ``move_action`` goal (move_action_capability.cpp): plan the request (feedback PLANNING), show the
        plan on /display_planned_path, and unless ``plan_only`` execute it (feedback MONITOR); the result carries
        the start state, the planned trajectory and, on success, the executed one."""
        result = MoveGroup.Result()
        if self._pool is None or self.planner is None:
            result.error_code = _code("FAILURE")
            result.error_code.message = "move_group has no robot yet (robot_description and robot_description_semantic)"
            handle.abort()
            return result
        goal = handle.request
        t0 = time.monotonic()
        handle.publish_feedback(MoveGroup.Feedback(state="PLANNING"))
        try:
            assert self._pool is not None
            with self._pool.using("plan"):
                start, traj = self._plan(goal.request)
        except PlanningError as err:
            result.error_code = _code(err.code)
            result.error_code.message = err.message
            self.get_logger().warning(
                f"planning for {quoted(goal.request.group_name)} failed: {err.code}: {err.message}"
            )
            handle.abort()
            return result
        except Exception as err:
            self.get_logger().error(f"planning failed: {type(err).__name__}: {err}")
            result.error_code = _code("FAILURE")
            result.error_code.message = f"internal error: {type(err).__name__}: {err}"
            handle.abort()
            return result
        result.planning_time = time.monotonic() - t0
        result.trajectory_start = self._robot_state(start)
        result.planned_trajectory = self._robot_trajectory(traj)
        # as MoveIt's move_group: every plan on /display_planned_path (RViz's and Foxglove's trajectory displays)
        self._display.publish(
            DisplayTrajectory(
                model_id=self.planner.semantics.robot_name if self.planner else "",
                trajectory=[result.planned_trajectory],
                trajectory_start=result.trajectory_start,
            )
        )
        if goal.planning_options.plan_only:
            result.error_code = _code("SUCCESS")
            handle.succeed()
            return result
        handle.publish_feedback(MoveGroup.Feedback(state="MONITOR"))
        code, message = self._run(result.planned_trajectory.joint_trajectory, handle)
        result.error_code = _code(code)
        result.error_code.message = message
        if code == "SUCCESS":
            result.executed_trajectory = result.planned_trajectory
        # move_action_capability.cpp: a preempted execution is a canceled goal (an aborted one when it was
        # stopped by the execution event, not cancelled: an executing goal cannot become canceled)
        _end_goal(handle, code, preempted="canceled" if handle.is_cancel_requested else "abort")
        return result

    def _execute_trajectory(self, handle: Any) -> ExecuteTrajectory.Result:
        """The ``execute_trajectory`` goal (execute_trajectory_action_capability.cpp): a trajectory beyond the
        limits is refused (INVALID_MOTION_PLAN) before anything moves; otherwise it runs on its controllers and
        anything but success ends the goal aborted, as MoveIt ends it."""
        result = ExecuteTrajectory.Result()
        trajectory = handle.request.trajectory.joint_trajectory
        problem = self._check_trajectory(trajectory)
        if problem is not None:
            result.error_code = _code("INVALID_MOTION_PLAN")
            result.error_code.message = problem
            handle.abort()
            return result
        code, message = self._run(trajectory, handle)
        result.error_code = _code(code)
        result.error_code.message = message
        # execute_trajectory_action_capability.cpp (Jazzy): anything but success is aborted, a cancelled or
        # stopped execution too (with PREEMPTED)
        _end_goal(handle, code, preempted="abort")
        return result

    def _check_trajectory(self, trajectory: JointTrajectory) -> str | None:
        """Why a trajectory sent to execute_trajectory cannot run (positions or speeds beyond the limits).

        On the query planner, under its lock, as every use of roboplan's scene: the simulation's scene updates
        (a message for every millimetre anything moves, so a stream while an arm executes) add, move and
        rebuild its pinocchio/coal models on another executor thread. Read without the lock, the limits
        came from a model being replaced: pymoveit2's execute_trajectory on a YuMi died of "double free
        or corruption" 4 runs in 4, while the MoveGroup action (which plans under the lock) did not."""
        pool = self._pool
        if pool is None:
            return "move_group has no robot yet"
        with pool.using("query") as planner:
            return self._check_trajectory_locked(trajectory, planner)

    def _check_trajectory_locked(self, trajectory: JointTrajectory, planner: ArmPlanner) -> str | None:
        """Why ``trajectory`` cannot be executed (None: it can): no points, a joint the robot lacks, a position
        outside its limits (the first point may be off by the start-state tolerance), or a speed between two
        points more than 1 % over the joint's velocity limit."""
        if not trajectory.points:
            return "the trajectory has no points"
        unknown = [j for j in trajectory.joint_names if j not in planner.joint_names]
        if unknown:
            return f"unknown joints {unknown}"
        lo, hi = planner.scene.getPositionLimitVectors("")
        speed = planner.velocity_limits  # not roboplan's getVelocityLimitVectors: see ArmPlanner.velocity_limits
        index = {n: i for i, n in enumerate(planner.joint_names)}
        prev = None
        for k, point in enumerate(trajectory.points):
            t = _seconds(point.time_from_start)
            for j, name in enumerate(trajectory.joint_names):
                i = index[name]
                p = point.positions[j]
                # the first point is where the arm is: a reading a little past a limit is allowed there,
                # as MoveIt allows a start state within start_state_max_bounds_error
                slack = START_BOUNDS_ERROR if k == 0 else 1e-4
                if not lo[i] - slack <= p <= hi[i] + slack:
                    return f"point {k}: {name} = {p:.4f} is outside its limits [{lo[i]:.4f}, {hi[i]:.4f}]"
                if prev is not None and t > prev[0]:
                    v = (p - prev[1][j]) / (t - prev[0])
                    if abs(v) > speed[name] * 1.01:
                        return f"point {k}: {name} moves at {v:.3f} rad/s, beyond its velocity limit {speed[name]:.3f}"
            prev = (t, list(point.positions))
        return None

    def _controllers_for(self, joints: list[str]) -> list[Controller]:
        """The controllers that execute a trajectory of ``joints``, as MoveIt's TrajectoryExecutionManager
        picks them: one that has every joint, else the fewest that together have them (a dual arm's group
        of both arms, one joint_trajectory_controller an arm), each then given its own joints' part. From
        moveit_controllers.yaml first, then the controller manager's active ones; [] when none cover them."""
        wanted = set(joints)
        listed: list[Controller] | None = None
        for pool_of in ("yaml", "ros2_control"):
            if pool_of == "yaml":
                pool = list(self._controllers)
            else:
                listed = self._ros2_control_controllers()
                pool = listed
            single = next((c for c in pool if wanted <= set(c.joints)), None)
            if single is not None:
                return [single]
            chosen = _cover(wanted, pool)
            if chosen:
                return chosen
        return _cover(wanted, [*self._controllers, *(listed or [])])

    def _ros2_control_controllers(self) -> list[Controller]:
        """The active joint_trajectory_controllers of the controller manager, as MoveIt's
        Ros2ControlManager finds them (moveit_controllers.yaml names no controllers then)."""
        from controller_manager_msgs.srv import ListControllers

        namespace = (self._param("ros_control_namespace") or "/").rstrip("/")  # MoveIt's parameter
        name = f"{namespace}/controller_manager/list_controllers"
        client = self._controller_lists.get(name)
        if client is None:
            client = self._controller_lists[name] = self._on_execution_thread(
                lambda: self._execution_node.create_client(ListControllers, name)
            )
        listed = any(n == name for n, _ in self._execution_node.get_service_names_and_types())
        if not client.wait_for_service(timeout_sec=2.0 if listed else 0.3):  # none: gz arms, say
            return []
        done = threading.Event()
        box: dict[str, Any] = {}

        def call() -> None:
            future = client.call_async(ListControllers.Request())
            future.add_done_callback(lambda f: (box.__setitem__("result", f.result()), done.set()))

        self._execution_executor.create_task(call)
        if not done.wait(5.0) or box.get("result") is None:
            return []
        out = []
        for c in box["result"].controller:
            if c.state != "active" or not c.type.endswith("JointTrajectoryController"):
                continue
            joints = tuple(dict.fromkeys(i.split("/")[0] for i in c.claimed_interfaces))
            out.append(Controller(c.name, f"{namespace}/{c.name}/follow_joint_trajectory", joints))
        return out

    def _position_topics(self, joints: list[str]) -> dict[str, str] | None:
        """gz-sim JointPositionController command topics (std_msgs/Float64, the default names
        ``/model/<model>/joint/<joint>/n0/cmd_pos`` on ROS, with a subscriber) for every one of ``joints``; None
        unless each joint has exactly one."""
        found: dict[str, list[str]] = {}
        for topic, types in self._execution_node.get_topic_names_and_types():
            m = GZ_CMD_POS.search(topic)
            if m and "std_msgs/msg/Float64" in types and m.group("joint") in joints:
                if self._execution_node.count_subscribers(topic) > 0:
                    found.setdefault(m.group("joint"), []).append(topic)
        if set(found) != set(joints) or any(len(t) != 1 for t in found.values()):
            return None
        return {j: t[0] for j, t in found.items()}

    def _wait_for_execution(self, joints: list[str]) -> tuple[list[Controller], bool, dict[str, str] | None]:
        """(the controllers of ``joints``, whether their actions are served, else the joints' gz command topics),
        waiting up to :data:`CONTROLLER_WAIT` for a served action or the topics to be discovered: right
        after a robot is spawned, a busy machine's graph may not list them, nor the controller manager
        that names the controller, yet (MoveIt's controller managers wait for their action servers
        likewise). Once the wait is over without either: (the controllers or [], False, None)."""
        deadline = time.monotonic() + CONTROLLER_WAIT
        while True:
            controllers = self._controllers_for(joints)
            if controllers and all(self._action_served(c.action) for c in controllers):
                return controllers, True, None
            topics = self._position_topics(joints)
            if topics is not None or time.monotonic() >= deadline:
                return controllers, False, topics
            time.sleep(0.1)  # the graph is kept by the middleware's threads

    def _action_served(self, action: str) -> bool:
        """Whether an action server of that name is in the graph now."""
        from rclpy.action.graph import get_action_names_and_types

        return any(name == action for name, _ in get_action_names_and_types(self._execution_node))

    def _stream(self, trajectory: JointTrajectory, topics: dict[str, str], handle: Any) -> tuple[str, str]:
        """Execute ``trajectory`` on gz JointPositionController arms: its positions, interpolated, streamed
        to each joint's command topic at :data:`STREAM_RATE_HZ` on the wall clock, then the end held until
        every joint is within :data:`STREAM_GOAL_TOLERANCE` of it (by /joint_states)."""
        joints = list(trajectory.joint_names)
        pubs = []
        for j in joints:
            pub = self._position_pubs.get(topics[j])
            if pub is None:
                pub = self._position_pubs[topics[j]] = self._on_execution_thread(
                    lambda t=topics[j]: self._execution_node.create_publisher(Float64, t, 10)
                )
            pubs.append(pub)
        points = [p for p in trajectory.points if len(p.positions) == len(joints)]
        if not points:
            return "INVALID_MOTION_PLAN", "the trajectory has no positions"
        times = np.array([_seconds(p.time_from_start) for p in points])
        positions = np.array([list(p.positions) for p in points], dtype=float)
        goal = positions[-1]

        def send(q: np.ndarray) -> None:
            for pub, v in zip(pubs, q):
                pub.publish(Float64(data=float(v)))

        def measured() -> np.ndarray | None:
            latest = self._latest_joints
            return np.array([latest[j] for j in joints]) if all(j in latest for j in joints) else None

        started = time.monotonic()
        duration = float(times[-1])
        period = 1.0 / STREAM_RATE_HZ
        while True:
            if handle.is_cancel_requested:
                now = measured()
                if now is not None:
                    send(now)  # stop where the arm is
                return "PREEMPTED", "stopped"
            t = time.monotonic() - started
            send(np.array([np.interp(t, times, positions[:, i]) for i in range(len(joints))]))
            if t >= duration:
                break
            time.sleep(period)
        # MoveIt's allowed_goal_duration_margin and more: the servos settle after the last set-point
        deadline = time.monotonic() + 0.2 * duration + 3.0
        settled = 0
        while True:
            now = measured()
            error = float(np.max(np.abs(now - goal))) if now is not None else math.inf
            # within the tolerance for 0.1 s on end: a servo swinging through the goal is not there yet
            settled = settled + 1 if error <= STREAM_GOAL_TOLERANCE else 0
            if settled >= STREAM_RATE_HZ / 10:
                return "SUCCESS", ""
            if handle.is_cancel_requested:
                if now is not None:
                    send(now)
                return "PREEMPTED", "stopped"
            if time.monotonic() > deadline:
                what = "no /joint_states for them" if now is None else f"{error:.4f} from the end"
                return "TIMED_OUT", f"the joints' command topics were streamed, but the arm is {what}"
            send(goal)
            time.sleep(period)

    def _run(self, trajectory: JointTrajectory, handle: Any) -> tuple[str, str]:
        """Send ``trajectory`` to its FollowJointTrajectory controller and wait; cancel it when ``handle`` is,
        or when a "stop" event comes. Without a controller serving its joints, gz-sim JointPositionController
        arms get it streamed."""
        stops = self._stops
        handle = _Stoppable(handle, lambda: self._stops != stops)
        joints = list(trajectory.joint_names)
        controllers, served, topics = self._wait_for_execution(joints)
        if not served and topics is not None:
            return self._stream(trajectory, topics, handle)
        if not controllers:
            return (
                "CONTROL_FAILED",
                f"no controller drives {joints} (moveit_controllers.yaml, an active joint_trajectory_controller "
                "of /controller_manager, or gz JointPositionController topics .../joint/<joint>/n0/cmd_pos)",
            )
        if len(controllers) == 1:
            return self._follow(controllers[0], trajectory, handle, served)
        # each controller its joints' part, all at once (MoveIt's distributeTrajectory), as one execution
        parts, given = [], set()
        for c in controllers:
            mine = [j for j in joints if j in c.joints and j not in given]
            given.update(mine)
            parts.append((c, _part(trajectory, mine)))
        results: list[tuple[str, str]] = [("CONTROL_FAILED", "not run")] * len(parts)

        def follow(i: int, controller: Controller, part: JointTrajectory) -> None:
            results[i] = self._follow(controller, part, handle, served)

        threads = [
            threading.Thread(target=follow, args=(i, c, part), name=f"execute {c.name}", daemon=True)
            for i, (c, part) in enumerate(parts)
        ]
        for t in threads:
            t.start()
        for t in threads:
            t.join()
        return next((r for r in results if r[0] == "PREEMPTED"), None) or next(
            (r for r in results if r[0] != "SUCCESS"), ("SUCCESS", "")
        )

    def _follow(
        self, controller: Controller, trajectory: JointTrajectory, handle: Any, served: bool
    ) -> tuple[str, str]:
        """Send ``trajectory`` to ``controller``'s FollowJointTrajectory action and wait; cancel it when
        ``handle`` is."""
        client = self._trajectory_clients.get(controller.action)
        if client is None:
            client = self._trajectory_clients[controller.action] = self._on_execution_thread(
                lambda: ActionClient(self._execution_node, FollowJointTrajectory, controller.action)
            )
        if not client.wait_for_server(timeout_sec=5.0 if served else 0.1):  # the graph was waited on above
            return "CONTROL_FAILED", f"controller action {controller.action} is not available"
        goal = FollowJointTrajectory.Goal(trajectory=trajectory)
        done = threading.Event()
        box: dict[str, Any] = {}

        def on_result(f: Any) -> None:
            box["result"] = f.result()
            done.set()

        def on_goal(f: Any) -> None:
            goal_handle = f.result()
            box["goal"] = goal_handle
            if not goal_handle.accepted:
                done.set()
                return
            goal_handle.get_result_async().add_done_callback(on_result)

        def on_feedback(_msg: Any) -> None:
            box["progress"] = time.monotonic()

        # every call on the client is made on its executor's thread: made from this one, a reply that came
        # back before rclpy filed the request was dropped and its future never completed (ros2/rclpy#1123)
        on_thread = self._execution_executor.create_task
        on_thread(lambda: client.send_goal_async(goal, feedback_callback=on_feedback).add_done_callback(on_goal))
        points = list(trajectory.points)
        duration = _seconds(points[-1].time_from_start) if points else 0.0
        # MoveIt's allowed_execution_duration_scaling (1.2) and allowed_goal_duration_margin (0.5 s), in
        # wall time; a simulation running slower than real time still reports progress through the
        # controller's feedback, so the wait goes on while feedback comes, up to four times as long.
        started = time.monotonic()
        expected = duration * 1.2 + 0.5
        cancelled = False
        while not done.wait(0.02):
            if handle.is_cancel_requested and not cancelled and "goal" in box:
                on_thread(box["goal"].cancel_goal_async)
                cancelled = True
            now = time.monotonic()
            handle_ = box.get("goal")
            silent = now - box.get("progress", started)
            ended = handle_ is not None and handle_.accepted and handle_.status in _ENDED
            if handle_ is not None and handle_.accepted and (ended or (now - started > expected and silent > 0.5)):
                # the controller says the goal ended, or its time is up and its feedback stopped, but no
                # result came: ask again every 0.5 s (a result response can be lost as a service reply
                # can; the server keeps results, and answers at once for a goal that is done)
                asked = box.setdefault("asked", now)
                if now - asked > 0.5:
                    box["asked"] = now
                    on_thread(lambda h=handle_: h.get_result_async().add_done_callback(on_result))
            quiet = silent > 3.0
            if now - started > expected and (quiet or now - started > 4 * expected + 5.0):
                if "goal" in box:
                    on_thread(box["goal"].cancel_goal_async)
                return (
                    "TIMED_OUT",
                    f"{controller.name} did not finish the {duration:.2f} s trajectory within {now - started:.1f} s",
                )
        if cancelled:
            return "PREEMPTED", "stopped"
        if "result" not in box:
            return "CONTROL_FAILED", f"{controller.name} rejected the trajectory"
        res = box["result"].result
        if res.error_code != FollowJointTrajectory.Result.SUCCESSFUL:
            return "CONTROL_FAILED", f"{controller.name}: {res.error_string or res.error_code}"
        return "SUCCESS", ""


class _Stoppable:
    """An action goal's handle as the execution loops see it: cancel requested when the client asked, or
    when ``stopped()`` (a "stop" on /trajectory_execution_event since the execution began)."""

    def __init__(self, handle: Any, stopped: Any) -> None:
        self._handle = handle
        self._stopped = stopped

    @property
    def is_cancel_requested(self) -> bool:
        return bool(self._handle.is_cancel_requested or self._stopped())


def _end_goal(handle: Any, code: str, preempted: str) -> None:
    """End an action goal as its MoveItErrorCodes name says: succeeded, aborted, or for PREEMPTED as the
    action's capability ends it (``preempted``: "canceled" or "abort")."""
    if code == "SUCCESS":
        handle.succeed()
    elif code == "PREEMPTED" and preempted == "canceled":
        handle.canceled()
    else:
        handle.abort()


def _cover(joints: set[str], controllers: list[Controller]) -> list[Controller]:
    """The fewest of ``controllers`` (greedy: the one with most of the joints left first) whose joints
    together are ``joints``; [] when they do not cover them."""
    left, pool, chosen = set(joints), list(controllers), []
    while left:
        best = max(pool, key=lambda c: len(left & set(c.joints)), default=None)
        if best is None or not left & set(best.joints):
            return []
        chosen.append(best)
        left -= set(best.joints)
        pool.remove(best)
    return chosen


def _part(trajectory: JointTrajectory, joints: list[str]) -> JointTrajectory:
    """``trajectory`` for ``joints`` alone (the same points in time, their columns)."""
    index = [list(trajectory.joint_names).index(j) for j in joints]
    points = []
    for p in trajectory.points:
        q = JointTrajectoryPoint(time_from_start=p.time_from_start)
        for field in ("positions", "velocities", "accelerations", "effort"):
            values = list(getattr(p, field))
            if len(values) == len(trajectory.joint_names):
                setattr(q, field, [values[i] for i in index])
        points.append(q)
    return JointTrajectory(header=trajectory.header, joint_names=list(joints), points=points)
