"""Robot and world descriptions: URDF, xacro, SDF and SRDF into one typed model.

Public entry points are :func:`load` (a file, dispatched by suffix) and
:func:`load_string` (text with an explicit or detected format). Both return a
:class:`LoadResult` whose ``value`` is a :class:`Model`, :class:`World` or
:class:`Semantics`, and raise :class:`ModelLoadError` carrying every
diagnostic when the input has errors.
"""

from __future__ import annotations

import dataclasses
import os
import re
from collections.abc import Mapping
from pathlib import Path

from ._bounded import BoundedWorker as BoundedWorker
from ._bounded import BoundExceeded as BoundExceeded
from ._bounded import run_bounded as run_bounded
from ._diagnostics import Diagnostic as Diagnostic
from ._diagnostics import DiagnosticSink as DiagnosticSink
from ._diagnostics import ErrorCode as ErrorCode
from ._diagnostics import ModelLoadError as ModelLoadError
from ._diagnostics import Severity as Severity
from ._diagnostics import SimError as SimError
from ._diagnostics import SourceLocation as SourceLocation
from ._diagnostics import excerpt as excerpt
from ._diagnostics import reply_text as reply_text
from ._formats import _SUFFIXES
from ._formats import FORMATS as FORMATS
from ._formats import XACRO_REFUSED as XACRO_REFUSED
from ._formats import detect_format as detect_format
from ._formats import format_for_path as format_for_path
from ._formats import xacro_markup as xacro_markup
from ._inertia import rotation_matrix as rotation_matrix
from ._meshes import MeshLook as MeshLook
from ._meshes import MeshReadError as MeshReadError
from ._meshes import load_mesh as load_mesh
from ._meshes import load_mesh_look as load_mesh_look
from ._meshes import load_trimesh_in_metres as load_trimesh_in_metres
from ._model import *  # noqa: F403  (the model dataclasses are the public surface)
from ._model import LoadResult, Model, World
from ._model_folders import ModelFolder as ModelFolder
from ._model_folders import model_folders as model_folders
from ._model_folders import read_model_folder as read_model_folder
from ._pose import *  # noqa: F403  (poses and rotations: part of the model's public surface)
from ._resources import ResourceResolver as ResourceResolver
from ._semantic_model import *  # noqa: F403  (SRDF semantics and ros2_control blocks: part of the model)
from ._semantic_model import Semantics
from ._untrusted import MAX_PARAMS_FILE_BYTES as MAX_PARAMS_FILE_BYTES
from ._untrusted import MAX_YAML_NODES as MAX_YAML_NODES
from ._untrusted import PARAMETERS_TEXT_TAG as PARAMETERS_TEXT_TAG
from ._untrusted import UntrustedInputError as UntrustedInputError
from ._untrusted import read_regular_file as read_regular_file
from ._untrusted import safe_load_bounded as safe_load_bounded
from ._untrusted import yaml_problem as yaml_problem
from ._xacro import expand_bounded as expand_xacro_bounded  # noqa: F401 - public
from ._xacro import read_description_file as read_description_file
from ._xacro import xacro_main as xacro_main
from ._xml import parse_floats as parse_floats


def load(
    path: str | os.PathLike[str],
    *,
    args: Mapping[str, str] | None = None,
    strict: bool = False,
    resolver: ResourceResolver | None = None,
    expand_xacro: bool = True,
) -> LoadResult:
    """Load a description file, dispatched by suffix.

    Args:
        path: a ``.urdf``, ``.xacro`` (``.urdf.xacro``), ``.sdf``/``.world`` or ``.srdf`` file.
        args: xacro ``$(arg)`` values.
        strict: turn warnings into errors.
        resolver: how ``package://``/``model://`` are found (default: environment).
        expand_xacro: run xacro on a xacro file (in a child process bounded in time and memory).
            True for files the user named themselves; False for files a remote request picked
            (the viewer's spawn panel), which then get ``XACRO_NOT_ALLOWED``.

    Returns:
        The loaded value and every warning.

    Raises:
        ModelLoadError: the file is missing, unreadable, has an unknown suffix, or has errors.
    """
    p = Path(path)
    fmt = format_for_path(p)
    try:
        text = p.read_text(encoding="utf-8")
    except FileNotFoundError:
        raise ModelLoadError(
            [Diagnostic(ErrorCode.FILE_NOT_FOUND, Severity.ERROR, f"no such file: {p}", SourceLocation(str(p)))]
        ) from None
    except (OSError, UnicodeDecodeError) as err:
        raise ModelLoadError(
            [Diagnostic(ErrorCode.FILE_READ_ERROR, Severity.ERROR, f"cannot read {p}: {err}", SourceLocation(str(p)))]
        ) from None
    if fmt is None:  # a suffix that does not tell (r2.urdf.xml): the root element does, as in spawn
        fmt = detect_format(text)
    if fmt is None:
        raise ModelLoadError(
            [
                Diagnostic(
                    ErrorCode.UNKNOWN_FORMAT,
                    Severity.ERROR,
                    f"unknown description format for '{p.name}': neither its suffix ("
                    + ", ".join(sorted(_SUFFIXES))
                    + ") nor its root element (<robot>, <sdf>) tells",
                    SourceLocation(str(p)),
                )
            ]
        )
    return load_string(
        text, format=fmt, source=str(p), args=args, strict=strict, resolver=resolver, expand_xacro=expand_xacro
    )


def load_string(
    text: str,
    *,
    format: str = "auto",
    source: str | None = None,
    args: Mapping[str, str] | None = None,
    strict: bool = False,
    resolver: ResourceResolver | None = None,
    expand_xacro: bool = False,
) -> LoadResult:
    """Load description text.

    Text is data: xacro markup in it is refused (``XACRO_NOT_ALLOWED``) unless the caller
    read the text from a file the user named and says so with ``expand_xacro=True``.
    xacro evaluates Python expressions, and its evaluator is no sandbox.

    Args:
        text: the XML.
        format: one of ``urdf``, ``xacro``, ``sdf``, ``srdf`` or ``auto`` (detect).
        source: the name used in diagnostics (default ``<string>.<format>``); relative
            paths in the text resolve against its folder when it is a real path.
        args: xacro ``$(arg)`` values.
        strict: turn warnings into errors.
        resolver: how ``package://``/``model://`` are found.
        expand_xacro: expand xacro (bounded in time and memory); only for a user's own file.

    Raises:
        ModelLoadError: with every diagnostic, when there is any error.
    """
    fmt = _resolved_format(text, format, source)
    source = source or f"<string>.{fmt}"
    resolver = resolver or ResourceResolver()
    if not source.startswith("<"):  # the folder of a file (the user's, or one found on the roots) may be read
        resolver = resolver.trusting(Path(source).parent)
    sink = DiagnosticSink(strict=strict)
    # a string has no folder: a relative path in it resolves against nothing (never the server's working
    # directory, which would let a peer on the ROS graph read whatever lies beside the server)
    base_dir = str(Path(source).parent) if not source.startswith("<") else None
    expanded = text
    if fmt == "xacro" and not expand_xacro:
        markup = xacro_markup(text)
        if markup is None:
            fmt = "urdf"  # a .xacro name, or an xmlns:xacro declaration, but nothing to expand
        else:
            sink.error(ErrorCode.XACRO_NOT_ALLOWED, XACRO_REFUSED.format(what=repr(markup)), SourceLocation(source))
            raise ModelLoadError(sink.items)
    if fmt == "xacro":
        from . import _xacro

        found = _xacro.expand_bounded(text, source=source, args=dict(args or {}), sink=sink, resolver=resolver)
        if found is None:
            sink.raise_if_errors()
            raise ModelLoadError(sink.items)
        expanded = found
        value = _parse_as(detect_format(expanded) or "urdf", expanded, source, sink, resolver, base_dir)
    else:
        value = _parse_as(fmt, text, source, sink, resolver, base_dir)
    sink.raise_if_errors()
    if value is None:
        raise ModelLoadError(sink.items)
    if isinstance(value, Model) and value.source_format in ("urdf", "xacro") and not value.urdf:
        from ._xml import LOCATION_ATTRIBUTE

        urdf = re.sub(rf'\s{LOCATION_ATTRIBUTE}="[^"]*"', "", expanded if fmt == "xacro" else text)
        value = dataclasses.replace(value, urdf=urdf)
    return LoadResult(value, tuple(sink.items))


def _resolved_format(text: str, format: str, source: str | None) -> str:
    """The format to read ``text`` as: ``format``, or detected from its root element for ``auto``; a
    ".urdf" that is really xacro is xacro (TurtleBot3's main branch ships one). ModelLoadError if none."""
    fmt = detect_format(text) if format == "auto" else format
    if fmt == "urdf" and detect_format(text) == "xacro":
        fmt = "xacro"
    if fmt is None or fmt not in FORMATS:
        raise ModelLoadError(
            [
                Diagnostic(
                    ErrorCode.UNKNOWN_FORMAT,
                    Severity.ERROR,
                    f"cannot tell the description format (got {format!r}); expected one of "
                    + ", ".join(FORMATS)
                    + " (a <robot> or <sdf> root element)",
                    SourceLocation(source or "<string>"),
                )
            ]
        )
    return fmt


def _parse_as(
    fmt: str, text: str, source: str, sink: DiagnosticSink, resolver: ResourceResolver, base_dir: str | None
) -> Model | World | Semantics | None:
    """Parse xacro-free ``text`` as URDF, SRDF or SDF (diagnostics into ``sink``)."""
    if fmt == "srdf":
        from . import _srdf

        return _srdf.parse_srdf(text, source=source, sink=sink)
    if fmt == "sdf":
        from . import _sdf

        return _sdf.parse_sdf(text, source=source, sink=sink, resolver=resolver, base_dir=base_dir)
    from . import _urdf

    return _urdf.parse_urdf(text, source=source, sink=sink, resolver=resolver, base_dir=base_dir)
