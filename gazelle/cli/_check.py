"""``gazelle check FILE``: load a description, print its diagnostics like a compiler and a summary.

Diagnostics go to stderr, one line each (``path:line: warning: [CODE] message``);
the summary goes to stdout. The exit code is 0 when there is no error, 1 otherwise
(including a missing file or an unknown format).
"""

from __future__ import annotations

import logging
import os
import sys
from collections.abc import Iterable, Mapping

from ..description import (
    Diagnostic,
    ErrorCode,
    Model,
    ModelLoadError,
    Semantics,
    Severity,
    SourceLocation,
    World,
    load,
)


def _plural(n: int, word: str) -> str:
    return f"{n} {word}" if n == 1 else f"{n} {word}s"


def _model_counts(model: Model) -> tuple[int, int, int, int]:
    """Links, joints, sensors and plugins (model plugins plus sensor plugins) of a model."""
    sensors = [s for lk in model.links for s in lk.sensors]
    plugins = len(model.plugins) + sum(len(s.plugins) for s in sensors)
    return len(model.links), len(model.joints), len(sensors), plugins


def _semantics_summary(sem: Semantics) -> str:
    """What an SRDF holds, counted (``gazelle check``'s one line for it)."""
    return ", ".join(
        [
            _plural(len(sem.groups), "group"),
            _plural(len(sem.group_states), "group state"),
            _plural(len(sem.end_effectors), "end effector"),
            _plural(len(sem.virtual_joints), "virtual joint"),
            _plural(len(sem.disabled_collisions), "disabled collision"),
        ]
    )


def summarize(value: object) -> str:
    """One line describing a loaded Model, World or Semantics."""
    if isinstance(value, Model):
        links, joints, sensors, plugins = _model_counts(value)
        line = (
            f"model {value.name}: {_plural(links, 'link')}, {_plural(joints, 'joint')}, "
            f"{_plural(sensors, 'sensor')}, {_plural(plugins, 'plugin')}"
        )
        if value.semantics is not None:
            line += f", {_plural(len(value.semantics.groups), 'group')}"
        return line
    if isinstance(value, World):
        totals = [0, 0, 0, 0]
        for m in value.models:
            for i, n in enumerate(_model_counts(m)):
                totals[i] += n
        links, joints, sensors, plugins = totals
        plugins += len(value.plugins)
        return (
            f"world {value.name}: {_plural(len(value.models), 'model')}, {_plural(len(value.lights), 'light')}, "
            f"{_plural(links, 'link')}, {_plural(joints, 'joint')}, {_plural(sensors, 'sensor')}, "
            f"{_plural(plugins, 'plugin')}"
        )
    if isinstance(value, Semantics):
        return f"semantics {value.robot_name}: {_semantics_summary(value)}"
    return f"{type(value).__name__}"


def _tally(diagnostics: Iterable[Diagnostic]) -> tuple[int, int]:
    """(errors, warnings) among ``diagnostics``."""
    errors = warnings = 0
    for d in diagnostics:
        if d.severity is Severity.ERROR:
            errors += 1
        else:
            warnings += 1
    return errors, warnings


def _print_diagnostics(diagnostics: Iterable[Diagnostic]) -> None:
    for d in diagnostics:
        print(d.format(), file=sys.stderr)


def _counts_line(errors: int, warnings: int) -> str:
    return f"{_plural(errors, 'error')}, {_plural(warnings, 'warning')}"


class _PluginLogs(logging.Handler):
    """Collects what plugins log while they are configured, as diagnostics at the plugin's file:line."""

    def __init__(self, locations: dict[str, SourceLocation | None], strict: bool) -> None:
        """Collect the warnings and errors the plugins' loggers print while ``gazelle check`` configures them, each
        located at its plugin's file:line (``strict``: as errors)."""
        super().__init__(logging.WARNING)
        self.locations = locations
        self.strict = strict
        self.found: list[Diagnostic] = []

    def emit(self, record: logging.LogRecord) -> None:
        """A plugin's log line as a diagnostic at the plugin's location (the simulation's own lines are left out:
        the audit reports the same, located)."""
        if record.name not in self.locations:
            return  # the simulation's own lines (the audit below says the same, located)
        error = record.levelno >= logging.ERROR or self.strict
        self.found.append(
            Diagnostic(
                ErrorCode.PLUGIN_CONFIG_INVALID,
                Severity.ERROR if error else Severity.WARNING,
                f"plugin '{record.name}': {record.getMessage()}",
                self.locations[record.name],
            )
        )


def simulation_diagnostics(value: object, *, strict: bool = False) -> list[Diagnostic]:
    """What spawning ``value`` would tell: plugins and sensors that will not run (with a "did you mean"),
    and what each plugin says while it is configured (a joint it cannot find, wheels that would
    drive backwards), by building it in a throwaway simulation of the default world."""
    from ..physics import WorldError
    from ..sim import Simulation
    from ..systems import audit_model, audit_world
    from ..worlds import default_world

    if isinstance(value, World):
        audit, models, world = audit_world(value), list(value.models), value
    elif isinstance(value, Model):
        audit, models, world = audit_model(value), [value], None
    else:
        return []
    sev = Severity.ERROR if strict else Severity.WARNING
    out = [Diagnostic(d.code, sev, d.message, d.location) for d in audit]
    locations = {p.name or p.filename: p.location for m in models for p in m.plugins}
    capture = _PluginLogs(locations, strict)
    root = logging.getLogger()
    saved_level = root.level
    root.addHandler(capture)
    root.setLevel(logging.WARNING)
    try:
        sim = Simulation(world if world is not None else default_world(), rtf=0.0, robot_state_publisher=False)
        if world is None:
            sim.spawn(models[0], name="checked")
        sim.step(1)
    except WorldError as err:
        where = models[0].location if models else None
        out.append(Diagnostic(ErrorCode.PLUGIN_CONFIG_INVALID, Severity.ERROR, f"cannot be simulated: {err}", where))
    finally:
        root.removeHandler(capture)
        root.setLevel(saved_level)
    return out + capture.found


def run_check(file: str | os.PathLike[str], *, args: Mapping[str, str] | None = None, strict: bool = False) -> int:
    """Load ``file``, print every diagnostic (stderr) and a summary (stdout).

    Returns:
        0 when the file loads without errors, 1 otherwise.
    """
    try:
        result = load(file, args=dict(args or {}), strict=strict)
    except ModelLoadError as err:
        _print_diagnostics(err.diagnostics)
        errors, warnings = _tally(err.diagnostics)
        print(_counts_line(max(errors, 1), warnings))
        return 1
    except Exception as err:  # a loader bug must still give one clear line, not a traceback
        print(f"{file}: error: internal error while loading: {type(err).__name__}: {err}", file=sys.stderr)
        print(_counts_line(1, 0))
        return 1
    diagnostics = list(result.diagnostics) + simulation_diagnostics(result.value, strict=strict)
    _print_diagnostics(diagnostics)
    errors, warnings = _tally(diagnostics)
    print(summarize(result.value))
    print(_counts_line(errors, warnings))
    return 1 if errors else 0
