"""Every service request gets a reply: failures as replies, never as a dead executor."""

from __future__ import annotations

import logging
from typing import Any

from ..description import reply_text


def failure_reply(res: Any, message: str) -> Any:
    """Mark any gazebo_msgs / simulation_interfaces / std_srvs response as failed with ``message``."""
    message = reply_text(message)
    if hasattr(res, "success"):
        res.success = False
    if hasattr(res, "status_message"):
        res.status_message = message
    result = getattr(res, "result", None)
    if result is not None and hasattr(result, "error_message"):
        result.result = 4  # simulation_interfaces Result.RESULT_OPERATION_FAILED
        result.error_message = message
    return res


def guarded_service(name: str, callback: Any) -> Any:
    """Wrap a service callback so that an unexpected exception becomes a failure reply.

    Without it, the exception would end up in the executor's thread: the request would get no
    reply and the executor would stop. The traceback goes to the log, the client gets one line.
    """
    log = logging.getLogger("gazelle.ros")

    def wrapper(request: Any, response: Any) -> Any:
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
