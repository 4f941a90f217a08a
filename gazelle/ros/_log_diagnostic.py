"""A load's diagnostic on a node's log at its level."""

from __future__ import annotations

from typing import TYPE_CHECKING

from ..description import Diagnostic, Severity

if TYPE_CHECKING:
    from rclpy.impl.rcutils_logger import RcutilsLogger


def log_diagnostic(logger: RcutilsLogger, d: Diagnostic) -> None:
    """``d`` on ``logger`` (an rclpy logger): an error the load went on past (a model not downloaded) at error
    level, as gz-sim logs it; everything else a load reports and still loads is a warning."""
    if d.severity is Severity.SKIPPED:
        logger.error(d.format())
    else:
        logger.warning(d.format())
