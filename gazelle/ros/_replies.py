"""Every service request gets a reply: failures as replies, never as a dead executor."""

from __future__ import annotations

import logging
import threading
import time
import warnings
from collections.abc import Callable
from typing import TYPE_CHECKING, Protocol, TextIO, TypeVar, runtime_checkable

from rclpy.action.server import ActionServer, CancelResponse, GoalResponse
from rclpy.qos import DurabilityPolicy, HistoryPolicy, QoSProfile, ReliabilityPolicy

from ..description import reply_text

if TYPE_CHECKING:
    from rclpy.action.server import ServerGoalHandle
    from rclpy.callback_groups import CallbackGroup
    from rclpy.node import Node
    from rclpy.service import Service

Req = TypeVar("Req")
Res = TypeVar("Res")
_Goal = TypeVar("_Goal")
_Result = TypeVar("_Result")
_Req_co = TypeVar("_Req_co", covariant=True)
_Res_co = TypeVar("_Res_co", covariant=True)
_Goal_co = TypeVar("_Goal_co", covariant=True)
_Result_co = TypeVar("_Result_co", covariant=True)


class ServiceType(Protocol[_Req_co, _Res_co]):
    """A generated service class (``simulation_interfaces.srv.SpawnEntity``), as rclpy's ``create_service`` takes
    it: what matters here are its Request and Response classes, which a callback of it takes and returns."""

    @property
    def Request(self) -> type[_Req_co]: ...

    @property
    def Response(self) -> type[_Res_co]: ...


class ActionType(Protocol[_Goal_co, _Result_co]):
    """A generated action class (``control_msgs.action.FollowJointTrajectory``): its Goal and Result classes."""

    @property
    def Goal(self) -> type[_Goal_co]: ...

    @property
    def Result(self) -> type[_Result_co]: ...


ServiceCallback = Callable[[Req, Res], Res]
"""A service callback: fills in and returns the response it is given for the request."""


@runtime_checkable
class _Succeeds(Protocol):
    """A response that says whether it succeeded (gazebo_msgs', std_srvs')."""

    success: bool


@runtime_checkable
class _SaysWhy(Protocol):
    """A response with a line for its client (gazebo_msgs')."""

    status_message: str


def failure_reply(res: Res, message: str) -> Res:
    """Mark any gazebo_msgs / simulation_interfaces / std_srvs response as failed with ``message``."""
    message = reply_text(message)
    if isinstance(res, _Succeeds):  # as hasattr: a runtime-checkable protocol checks its members are there
        res.success = False
    if isinstance(res, _SaysWhy):
        res.status_message = message
    result = getattr(res, "result", None)
    if result is not None and hasattr(result, "error_message"):
        result.result = 4  # simulation_interfaces Result.RESULT_OPERATION_FAILED
        result.error_message = message
    return res


def guarded_service(name: str, callback: ServiceCallback[Req, Res]) -> ServiceCallback[Req, Res]:
    """Wrap a service callback so that an unexpected exception becomes a failure reply.

    Without it, the exception would end up in the executor's thread: the request would get no
    reply and the executor would stop. The traceback goes to the log, the client gets one line.
    """
    log = logging.getLogger("gazelle.ros")

    def wrapper(request: Req, response: Res) -> Res:
        try:
            return callback(request, response)
        except Exception as err:
            log.error(f"{name}: internal error while serving a request", exc_info=err)
            return failure_reply(response, f"{name}: internal error: {type(err).__name__}: {err}")

    return wrapper


def with_warnings(warnings: list[str]) -> str:
    """What a success reply adds about the description's warnings (they are also in the server's log)."""
    if not warnings:
        return ""
    more = f" (and {len(warnings) - 1} more in the server's log)" if len(warnings) > 1 else ""
    return reply_text(f"; {len(warnings)} warning(s): {warnings[0]}{more}")


SERVICE_QOS = QoSProfile(
    history=HistoryPolicy.KEEP_LAST,
    depth=1000,
    reliability=ReliabilityPolicy.RELIABLE,
    durability=DurabilityPolicy.VOLATILE,
)
"""The QoS of every service gazelle serves: ROS's services default, but 1000 deep instead of 10.

One service's replies to all its clients go out through one writer. With 10 kept, a reply that the
middleware lost on the way (a full shared-memory port on a busy machine) was gone for good once ten more
replies had gone out to other clients before the client's reader asked for it again: 8 clients calling
at once lost one reply in a loaded test run ("no reply in 30 s"). The request side gets the same depth,
so a burst of callers is not cut to the last ten."""


def serve(
    node: Node,
    srv_type: ServiceType[Req, Res],
    name: str,
    callback: ServiceCallback[Req, Res],
    callback_group: CallbackGroup | None,
) -> Service:
    """``node.create_service`` with :data:`SERVICE_QOS`, its lost replies offered again
    (:func:`resend_lost_replies`); returns the service."""
    service = node.create_service(srv_type, name, callback, qos_profile=SERVICE_QOS, callback_group=callback_group)
    return resend_lost_replies(service, name)


def serve_action(
    node: Node,
    action_type: ActionType[_Goal, _Result],
    name: str,
    execute: Callable[[ServerGoalHandle], _Result],
    callback_group: CallbackGroup | None,
    accept: Callable[[_Goal], GoalResponse] | None = None,
) -> ActionServer:
    """An rclpy ActionServer for ``action_type`` on ``name``: ``execute`` runs an accepted goal, ``accept(goal)``
    says whether a goal is taken (None: every goal, as MoveIt's and simulation_interfaces' servers do), and a
    cancel request is always accepted (the execute callback decides how the goal ends)."""
    return ActionServer(
        node,
        action_type,
        name,
        execute_callback=execute,
        goal_callback=accept if accept is not None else (lambda _goal: GoalResponse.ACCEPT),
        cancel_callback=lambda _handle: CancelResponse.ACCEPT,
        callback_group=callback_group,
    )


class _Replying(Protocol):
    """What :func:`resend_lost_replies` uses of a service: the method the executor sends each reply with."""

    send_response: Callable[..., None]


_S = TypeVar("_S", bound=_Replying)

RESEND_SEC = 10.0
"""How long a reply the middleware could not deliver is offered again."""

_LOST = "failed to send response (timeout)"
_sending = threading.local()
_hook_lock = threading.Lock()
_hooked = False


def _hook_warnings() -> None:
    """Notice rclpy's "failed to send response (timeout)" on the thread that sends.

    rclpy says so with a RuntimeWarning and nothing else: Fast DDS waits 100 ms for the client's
    response reader to be discovered and then drops the reply. The filter makes the warning reach
    the hook every time (not only once per line); every other warning goes on as before.
    """
    global _hooked
    with _hook_lock:
        if _hooked:
            return
        _hooked = True
        warnings.filterwarnings("always", message=r"failed to send response \(timeout\)", category=RuntimeWarning)
        shown = warnings.showwarning

        def showwarning(
            message: Warning | str,
            category: type[Warning],
            filename: str,
            lineno: int,
            file: TextIO | None = None,
            line: str | None = None,
        ) -> None:
            if getattr(_sending, "active", False) and str(message).startswith(_LOST):
                _sending.lost = True
                return
            shown(message, category, filename, lineno, file, line)

        warnings.showwarning = showwarning


def _send(send: Callable[[object, object], None], response: object, header: object) -> bool:
    """Send once; False when the middleware dropped the reply for want of a matched reader."""
    _sending.active, _sending.lost = True, False
    try:
        send(response, header)
    finally:
        _sending.active = False
    return not _sending.lost


def resend_lost_replies(service: _S, name: str) -> _S:
    """Make ``service`` offer a reply again until the client's reader is discovered (at most
    :data:`RESEND_SEC`), on a thread of its own; returns ``service``.

    A client that calls the moment the service appears (``wait_for_service`` only knows the request
    side) otherwise waits forever: the server handled the request, and the reply went nowhere.
    Seen as "service /get_entity_state did not answer within 15 s" right after a launch.
    """
    _hook_warnings()
    send = service.send_response
    log = logging.getLogger("gazelle.ros")

    def resend(response: object, header: object) -> None:
        deadline = time.monotonic() + RESEND_SEC
        tries = 1
        while time.monotonic() < deadline:
            tries += 1
            try:
                if _send(send, response, header):  # each try waits up to 100 ms in the middleware
                    log.debug(f"{name}: reply delivered on try {tries}")
                    return
            except Exception:  # the service was destroyed meanwhile: nobody left to answer for
                return
            time.sleep(0.05)  # a breath between tries when the middleware answers at once
        log.warning(f"{name}: a reply was not delivered in {RESEND_SEC:g} s: the client's reader was never discovered")

    def send_response(response: object, header: object) -> None:
        if not _send(send, response, header):
            threading.Thread(target=resend, args=(response, header), name=f"resend {name}", daemon=True).start()

    service.send_response = send_response  # the executor sends every reply through this attribute
    return service
