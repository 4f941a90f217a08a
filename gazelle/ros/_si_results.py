"""simulation_interfaces' result codes as the services reply with them: :func:`_result`, the refusal a request
fails with (:class:`_Refused`, a result code and one line), and :func:`_attempt`, which turns what the world
raised into a Result. Shared by every module that serves a part of the standard."""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping
from typing import TypeVar

from simulation_interfaces.msg import Result

from .._errors import SimError
from ..description import reply_text
from ..physics import ErrorKind, WorldError


def _result(code: int, message: str = "") -> Result:
    return Result(result=code, error_message=reply_text(message))


OK = Result.RESULT_OK


class _Refused(SimError):
    """A request failed with a result code."""

    def __init__(self, code: int, message: str):
        super().__init__(message)
        self.code = code


_T = TypeVar("_T")


def _attempt(fn: Callable[[], _T], codes: Mapping[ErrorKind, int] | None = None) -> tuple[Result, _T | None]:
    """Run ``fn`` and say how it went as a simulation_interfaces Result, with its value when it succeeded
    (None otherwise). A refusal answers with its own code; a WorldError by its kind through ``codes``
    (a missing entity is RESULT_NOT_FOUND unless ``codes`` says otherwise, any other kind
    RESULT_OPERATION_FAILED); a simulation that did not answer in time, RESULT_OPERATION_FAILED."""
    try:
        value = fn()
    except _Refused as err:
        return _result(err.code, str(err)), None
    except WorldError as err:
        table = {ErrorKind.NOT_FOUND: Result.RESULT_NOT_FOUND, **(codes or {})}
        return _result(table.get(err.kind, Result.RESULT_OPERATION_FAILED), str(err)), None
    except TimeoutError as err:
        return _result(Result.RESULT_OPERATION_FAILED, f"the simulation did not answer: {err}"), None
    return _result(OK), value


def _finite(*values: float) -> bool:
    return all(math.isfinite(v) for v in values)
