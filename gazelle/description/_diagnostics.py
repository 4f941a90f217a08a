"""Diagnostics: every problem found in a user's file, with a stable code and a location.

Loaders report into a :class:`DiagnosticSink`; at the API boundary one
:class:`ModelLoadError` is raised carrying every diagnostic, so users see all
their mistakes at once, printed like a compiler::

    robot.urdf:42: error: [JOINT_PARENT_INVALID] joint 'wheel_l' has unknown parent link 'bse'
"""

from __future__ import annotations

import enum
import re
from dataclasses import dataclass, field

from .._errors import SimError

EXCERPT_CHARS = 160
"""The longest excerpt of a user's value that a message echoes (then ``…`` and its length)."""
MESSAGE_CHARS = 600
"""The longest diagnostic message; error replies go over the wire, so they stay short."""
_QUOTED = re.compile(rf"'[^'\n]{{{EXCERPT_CHARS + 1},}}'|\"[^\"\n]{{{EXCERPT_CHARS + 1},}}\"")


def excerpt(value: object, limit: int = EXCERPT_CHARS) -> str:
    """``repr(value)`` cut to ``limit`` characters, saying how long it was: what an error may echo."""
    text = value if isinstance(value, str) else str(value)
    if len(text) <= limit:
        return repr(text)
    return repr(text[:limit]) + f"… ({len(text)} characters)"


def shorten_message(message: str, limit: int = MESSAGE_CHARS) -> str:
    """Cut every quoted value longer than :data:`EXCERPT_CHARS`, and the whole to ``limit`` characters."""
    out = _QUOTED.sub(
        lambda m: m.group(0)[: EXCERPT_CHARS + 1] + f"…{m.group(0)[0]} ({len(m.group(0)) - 2} characters)", message
    )
    if len(out) > limit:
        out = out[:limit] + f"… ({len(out)} characters)"
    return out


REPLY_CHARS = 4000
"""The longest error text a service reply carries."""


def reply_text(message: str) -> str:
    """An error message made fit for a service reply: excerpts of values, at most :data:`REPLY_CHARS`."""
    return shorten_message(message, REPLY_CHARS)


class Severity(enum.Enum):
    """How bad a diagnostic is."""

    WARNING = "warning"
    ERROR = "error"
    SKIPPED = "skipped"
    """An error the load goes on past: a part the user must get (a model not downloaded) is left out, as gz-sim
    and Gazebo Classic log an error for a model they cannot find and load the rest of the world. Shown as
    ``error``; it does not fail the load (strict mode makes it an :attr:`ERROR`)."""


class ErrorCode(enum.Enum):
    """Stable codes for diagnostics. Tests check the code; humans read the message."""

    # generic XML / file problems
    FILE_NOT_FOUND = "FILE_NOT_FOUND"
    FILE_READ_ERROR = "FILE_READ_ERROR"
    XML_PARSE_ERROR = "XML_PARSE_ERROR"
    UNKNOWN_FORMAT = "UNKNOWN_FORMAT"
    XACRO_ERROR = "XACRO_ERROR"
    XACRO_NOT_ALLOWED = "XACRO_NOT_ALLOWED"
    """xacro markup in a description that arrived as a string: strings are data, never evaluated."""
    ROOT_ELEMENT_INVALID = "ROOT_ELEMENT_INVALID"
    ELEMENT_MISSING = "ELEMENT_MISSING"
    ATTRIBUTE_MISSING = "ATTRIBUTE_MISSING"
    ATTRIBUTE_INVALID = "ATTRIBUTE_INVALID"
    VALUE_INVALID = "VALUE_INVALID"
    ELEMENT_UNSUPPORTED = "ELEMENT_UNSUPPORTED"
    ATTRIBUTE_UNSUPPORTED = "ATTRIBUTE_UNSUPPORTED"
    # structure
    DUPLICATE_NAME = "DUPLICATE_NAME"
    LINK_MISSING = "LINK_MISSING"
    JOINT_PARENT_INVALID = "JOINT_PARENT_INVALID"
    JOINT_CHILD_INVALID = "JOINT_CHILD_INVALID"
    JOINT_TYPE_INVALID = "JOINT_TYPE_INVALID"
    JOINT_AXIS_INVALID = "JOINT_AXIS_INVALID"
    KINEMATIC_LOOP = "KINEMATIC_LOOP"
    MULTIPLE_ROOTS = "MULTIPLE_ROOTS"
    FRAME_INVALID = "FRAME_INVALID"
    FRAME_CYCLE = "FRAME_CYCLE"
    MATERIAL_UNDEFINED = "MATERIAL_UNDEFINED"
    # physics-relevant values
    INERTIA_MISSING = "INERTIA_MISSING"
    INERTIA_INVALID = "INERTIA_INVALID"
    INERTIAL_NESTED = "INERTIAL_NESTED"
    MASS_INVALID = "MASS_INVALID"
    GEOMETRY_INVALID = "GEOMETRY_INVALID"
    MESH_NOT_FOUND = "MESH_NOT_FOUND"
    MESH_LOAD_ERROR = "MESH_LOAD_ERROR"
    URI_UNRESOLVED = "URI_UNRESOLVED"
    # extensions
    GAZEBO_REFERENCE_INVALID = "GAZEBO_REFERENCE_INVALID"
    PLUGIN_UNSUPPORTED = "PLUGIN_UNSUPPORTED"
    PLUGIN_CONFIG_INVALID = "PLUGIN_CONFIG_INVALID"
    SDF_VERSION_UNSUPPORTED = "SDF_VERSION_UNSUPPORTED"
    CONTROL_JOINT_INVALID = "CONTROL_JOINT_INVALID"
    """A ``<ros2_control>`` block names a joint the robot does not have."""
    SRDF_REFERENCE_INVALID = "SRDF_REFERENCE_INVALID"
    # documents
    FRAGMENT = "FRAGMENT"
    """A description with no links or joints (an include file of macros, properties, extensions)."""


@dataclass(frozen=True, slots=True)
class SourceLocation:
    """Where something came from in a user's file."""

    file: str
    """Path of the file, or a synthetic name such as ``<string>.urdf``."""
    line: int | None = None
    """1-based line number, when known."""

    def __str__(self) -> str:
        return f"{self.file}:{self.line}" if self.line is not None else self.file


@dataclass(frozen=True, slots=True)
class Diagnostic:
    """One problem found while loading a description."""

    code: ErrorCode
    """Stable machine-readable code."""
    severity: Severity
    """Warning or error."""
    message: str
    """Human-readable message."""
    location: SourceLocation | None = None
    """File and line the problem is at, if known."""

    def format(self) -> str:
        """Format like a compiler: ``file:line: error: [CODE] message``."""
        where = f"{self.location}: " if self.location is not None else ""
        level = "error" if self.severity is Severity.SKIPPED else self.severity.value
        return f"{where}{level}: [{self.code.value}] {self.message}"

    def __str__(self) -> str:
        return self.format()


class ModelLoadError(SimError, ValueError):
    """A description could not be loaded. ``.diagnostics`` holds every problem found."""

    def __init__(self, diagnostics: tuple[Diagnostic, ...] | list[Diagnostic]):
        self.diagnostics: tuple[Diagnostic, ...] = tuple(diagnostics)
        errors = [d for d in self.diagnostics if d.severity is Severity.ERROR]
        shown = errors or list(self.diagnostics)
        super().__init__("\n".join(d.format() for d in shown) or "model could not be loaded")

    def summary(self, max_items: int = 8) -> str:
        """The first ``max_items`` errors and how many more: what a service reply carries."""
        errors = [d for d in self.diagnostics if d.severity is Severity.ERROR] or list(self.diagnostics)
        lines = [d.format() for d in errors[:max_items]]
        if len(errors) > max_items:
            lines.append(f"... and {len(errors) - max_items} more errors")
        return "\n".join(lines) or "model could not be loaded"

    @property
    def first(self) -> Diagnostic | None:
        """The first error (or diagnostic) found, handy for one-line reports."""
        for d in self.diagnostics:
            if d.severity is Severity.ERROR:
                return d
        return self.diagnostics[0] if self.diagnostics else None


@dataclass
class DiagnosticSink:
    """Collects diagnostics while loading; a policy decides what happens at the end."""

    strict: bool = False
    """When true, warnings count as errors."""
    items: list[Diagnostic] = field(default_factory=list)
    _hard_errors: int = field(default=0, repr=False)

    def error(self, code: ErrorCode, message: str, location: SourceLocation | None = None) -> None:
        """Report an error (long values in the message are cut to an excerpt)."""
        self._hard_errors += 1
        self.items.append(Diagnostic(code, Severity.ERROR, shorten_message(message), location))

    def warning(self, code: ErrorCode, message: str, location: SourceLocation | None = None) -> None:
        """Report a warning (an error in strict mode)."""
        sev = Severity.ERROR if self.strict else Severity.WARNING
        self.items.append(Diagnostic(code, sev, shorten_message(message), location))

    def skipped(self, code: ErrorCode, message: str, location: SourceLocation | None = None) -> None:
        """Report an error the load goes on past (:attr:`Severity.SKIPPED`; an error in strict mode)."""
        if self.strict:
            self.error(code, message, location)
            return
        self.items.append(Diagnostic(code, Severity.SKIPPED, shorten_message(message), location))

    @property
    def has_errors(self) -> bool:
        """Whether any error has been reported."""
        return any(d.severity is Severity.ERROR for d in self.items)

    @property
    def has_hard_errors(self) -> bool:
        """Whether any error was reported as an error (not a warning promoted by strict mode).

        Loaders use this to decide whether later checks can still run: in strict mode a
        promoted warning must not hide the structure errors behind it.
        """
        return self._hard_errors > 0

    def raise_if_errors(self) -> None:
        """Raise :class:`ModelLoadError` with everything collected if there is any error."""
        if self.has_errors:
            raise ModelLoadError(self.items)

    def extend(self, diagnostics: tuple[Diagnostic, ...] | list[Diagnostic]) -> None:
        """Add diagnostics collected elsewhere."""
        self._hard_errors += sum(1 for d in diagnostics if d.severity is Severity.ERROR)
        self.items.extend(diagnostics)
