"""xacro expansion through the real ``xacro`` package, with file:line kept for every element.

:func:`expand` runs xacro's own ``process_doc`` with four scoped changes, undone afterwards
(xacro keeps its state in module globals, so expansions are serialised by a lock):

- ``$(find pkg)`` resolves through our :class:`ResourceResolver` (search paths, then the
  ament index) instead of ``ament_index_python``;
- xacro's ``parse`` is replaced by a line-aware one: every element remembers the file and
  line it was read from (minidom user data, copied when macros clone nodes), and every
  non-xacro element also gets a :data:`._xml.LOCATION_ATTRIBUTE` attribute, which survives
  macro expansion into the output so the URDF parser can point at the original xacro line;
- the functions xacro calls per element are wrapped to track which element is being
  processed, so an error (undefined property, bad expression, missing include) is
  reported at that element's file and line, even inside an included file or a macro;
- xacro's warnings go to the diagnostic sink instead of stderr.

Any failure becomes a diagnostic (``XACRO_ERROR``, or ``XML_PARSE_ERROR`` for malformed
XML); nothing is raised.
"""

from __future__ import annotations

import contextlib
import functools
import os
import threading
import xml.dom
import xml.dom.minidom
import xml.parsers.expat
from collections.abc import Callable, Iterator, Mapping
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any
from xml.dom import expatbuilder

import xacro
import xacro.substitution_args as xacro_subst

from .._errors import SimError
from ._diagnostics import DiagnosticSink, ErrorCode, SourceLocation
from ._formats import detect_format
from ._resources import ResourceResolver
from ._xml import LOCATION_ATTRIBUTE, encode_location, relax_comments

_LOCK = threading.Lock()
_USER_DATA_KEY = "gazelle.location"
_TRACKED = ("eval_all", "process_include", "grab_macro", "grab_property", "handle_macro_call")
"""xacro functions whose first argument is the element being processed."""


class _PackageNotFound(SimError):
    """``$(find pkg)`` named a package the resolver does not know."""

    def __init__(self, package: str):
        """A ``$(find package)`` that no resource root holds, naming where gazelle looked."""
        super().__init__(
            f"package '{package}' not found (searched GAZELLE_RESOURCE_PATH, GZ_SIM_RESOURCE_PATH, "
            "GAZEBO_MODEL_PATH, ROS_PACKAGE_PATH and the ament index)"
        )


class _IncludedXmlError(SimError):
    """A file read by xacro (the main text or an include) is not well-formed XML."""

    def __init__(self, file: str | None, line: int | None, message: str):
        super().__init__(message)
        self.location_file = file
        self.line = line


class _CopyOnClone:
    """minidom user-data handler: clones (macro expansion) keep their origin's location."""

    def handle(self, operation: int, key: str, data: object, src: object, dst: Any) -> None:
        if operation == xml.dom.UserDataHandler.NODE_CLONED and dst is not None:
            dst.setUserData(key, data, self)


_COPY_ON_CLONE = _CopyOnClone()


class _LineBuilder(expatbuilder.ExpatBuilderNS):
    """minidom builder that records each element's file and line."""

    def __init__(self, file: str) -> None:
        super().__init__()
        self._file = file

    def start_element_handler(self, name: str, attributes: list[str]) -> None:
        """As minidom builds each element, note its file and line (copied with the node when xacro clones it into a
        macro's expansion), and write them as a location attribute the URDF parser reads back, so a diagnostic of
        the expanded URDF names the line in the user's xacro file."""
        super().start_element_handler(name, attributes)
        node = self.curNode
        line = int(self._parser.CurrentLineNumber)  # pyright: ignore[reportAttributeAccessIssue] - expat's parser object, which minidom's stubs do not declare
        node.setUserData(_USER_DATA_KEY, (self._file, line), _COPY_ON_CLONE)
        if not node.tagName.startswith("xacro:"):  # xacro checks its own tags' attributes  # pyright: ignore[reportAttributeAccessIssue] - minidom's stubs type nodes as Node, not Element
            node.setAttribute(LOCATION_ATTRIBUTE, encode_location(self._file, line))  # pyright: ignore[reportAttributeAccessIssue] - minidom's stubs type nodes as Node, not Element


def _parse_located(data: str | bytes, file: str) -> xml.dom.minidom.Document:
    """Parse XML into a located minidom document (raises :class:`_IncludedXmlError`).

    Comments with ``--`` are accepted as TinyXML accepts them (see :func:`._xml.relax_comments`).
    """
    if isinstance(data, bytes):
        try:
            data = data.decode("utf-8")
        except UnicodeDecodeError as err:
            raise _IncludedXmlError(file, None, f"not UTF-8: {err}") from None
    data, _lines = relax_comments(data)
    try:
        return _LineBuilder(file).parseString(data)
    except xml.parsers.expat.ExpatError as err:
        raise _IncludedXmlError(file, err.lineno, f"malformed XML: {err}") from None


def node_location(node: Any) -> SourceLocation | None:
    """The file:line an element (or its nearest located ancestor) was read from."""
    while node is not None:
        getter = getattr(node, "getUserData", None)
        data = getter(_USER_DATA_KEY) if getter is not None else None
        if data is not None:
            return SourceLocation(data[0], data[1])
        node = getattr(node, "parentNode", None)
    return None


@dataclass
class _Tracker:
    """Which element xacro is processing, to place errors and warnings."""

    sink: DiagnosticSink
    source: str
    stack: list[Any] = field(default_factory=list)
    last: Any = None

    def location(self) -> SourceLocation:
        """Location of the element being processed (the document when unknown)."""
        return node_location(self.last) or SourceLocation(self.source)

    def track(self, fn: Callable[..., Any]) -> Callable[..., Any]:
        """Wrap a xacro function taking an element first: errors get that element's location."""

        @functools.wraps(fn)
        def wrapper(node: Any, *args: Any, **kwargs: Any) -> Any:
            """Run one of xacro's element handlers with its node on the stack: an exception leaving it is stamped
            with the innermost element's location (once), which the error then names."""
            self.stack.append(node)
            self.last = node
            try:
                result = fn(node, *args, **kwargs)
            except Exception as err:  # re-raised; only annotated with the innermost location
                if getattr(err, "gazelle_location", None) is None:
                    with contextlib.suppress(AttributeError):
                        err.gazelle_location = self.location()  # type: ignore[attr-defined] - the location rides on whatever exception xacro raised, which declares no such field
                raise
            self.stack.pop()
            self.last = self.stack[-1] if self.stack else None
            return result

        return wrapper

    def touch(self, fn: Callable[..., Any]) -> Callable[..., Any]:
        """Wrap ``check_attrs``: the element it checks is the one being processed."""

        @functools.wraps(fn)
        def wrapper(node: Any, *args: Any, **kwargs: Any) -> Any:
            self.last = node
            return fn(node, *args, **kwargs)

        return wrapper

    def warning(self, *args: Any, **_: Any) -> None:
        """Replacement for xacro's stderr warnings."""
        text = " ".join(str(a) for a in args)
        self.sink.warning(ErrorCode.XACRO_ERROR, f"xacro: {text}", self.location())


def _find_with(resolver: ResourceResolver) -> Callable[[str], str]:
    """xacro's ``$(find pkg)`` through gazelle's resource roots (raising :class:`_PackageNotFound` for a package
    none holds)."""

    def find(package: str) -> str:
        path = resolver.find_package(package)
        if path is None:
            raise _PackageNotFound(package)
        return str(path)

    return find


def _xacro_parse(inp: Any, filename: str | None = None) -> Any:
    """Drop-in for ``xacro.parse`` producing located documents."""
    if inp is None:
        try:
            with open(os.path.join(xacro.root_dir, filename or ""), "rb") as f:
                data = f.read()
        except OSError as err:
            xacro.filestack.pop()  # as xacro does: the failing file is not "current"
            raise xacro.XacroException(f"{err.strerror}: {err.filename}", exc=err) from None
        return _parse_located(data, filename or "<string>")
    if isinstance(inp, (str, bytes)):
        return _parse_located(inp, filename or "<string>")
    if hasattr(inp, "read"):
        return _parse_located(inp.read(), filename or "<string>")
    return inp


@contextlib.contextmanager
def _patched(resolver: ResourceResolver, tracker: _Tracker) -> Iterator[None]:
    """Install our hooks into the xacro modules, restoring everything afterwards.

    xacro (the PyPI package ROS uses) is a module of globals, not an object: ``$(find pkg)`` is answered by
    a function in its substitution table, files are read by ``xacro.parse``, warnings printed by
    ``xacro.warning``. To expand a user's file unchanged and still name file:line in every message, the
    hooks answer ``$(find)`` from gazelle's resource roots (a package outside them is an error, not a file
    read from anywhere), parse with line numbers kept, and record which element each step was on. Each
    global is saved and put back (and xacro's include list and argument table emptied), so one expansion
    leaves nothing for the next, in this process or a test's."""
    find = _find_with(resolver)
    patches: list[tuple[Any, str, Any]] = [
        (xacro_subst, "_eval_find", find),
        (xacro, "parse", _xacro_parse),
        (xacro, "warning", tracker.warning),
        (xacro, "print_location", lambda *a, **k: None),
        (xacro, "check_attrs", tracker.touch(xacro.check_attrs)),
    ]
    patches += [(xacro, name, tracker.track(getattr(xacro, name))) for name in _TRACKED]
    saved = [(mod, name, getattr(mod, name)) for mod, name, _ in patches]
    saved_find = xacro_subst._eval_dict["find"]
    saved_stacks = (xacro.filestack, xacro.macrostack)
    try:
        for mod, name, value in patches:
            setattr(mod, name, value)
        xacro_subst._eval_dict["find"] = find
        yield
    finally:
        for mod, name, value in saved:
            setattr(mod, name, value)
        xacro_subst._eval_dict["find"] = saved_find
        xacro.filestack, xacro.macrostack = saved_stacks
        xacro.substitution_args_context["arg"] = {}
        xacro.all_includes.clear()


def _describe(err: BaseException) -> str:
    """A one-line message for a xacro failure, without xacro's repeated wrapping.

    xacro wraps an error once per level it passes through (an include in a macro in an include), each
    wrapper repeating the message with a suffix naming where; unwrapped here into the innermost message,
    then the places, so the user reads the cause first. A missing package and a name error are shown as
    they are; anything else with its type, as it is a xacro failure the user may need to search for."""
    parts: list[str] = []
    suffixes: list[str] = []
    node: BaseException | None = err
    while node is not None:
        if isinstance(node, xacro.XacroException):
            msg = str(node.args[0]) if node.args and node.args[0] else ""
            if node.suffix:
                suffixes.append(" ".join(str(node.suffix).split()))
            if msg and not msg.startswith("<class"):
                parts.append(msg.strip())
            if isinstance(node.exc, OSError) and msg:
                break
            node = node.exc
        elif isinstance(node, MemoryError):
            parts.append("out of memory (the memory limit of xacro expansion is set by GAZELLE_XACRO_MEMORY_MB)")
            break
        else:
            plain = isinstance(node, (NameError, _PackageNotFound, xacro_subst.SubstitutionException))
            parts.append(str(node) if plain else f"{type(node).__name__}: {node}")
            break
    text = " ".join(p for p in parts if p) or type(err).__name__
    return text + "".join(f" ({s})" for s in suffixes)


def _macro_context() -> str:
    names = [str(m.body.getAttribute("name")) for m in (xacro.macrostack or []) if getattr(m, "body", None)]
    return f" (in macro {' <- '.join(repr(n) for n in reversed(names))})" if names else ""


def _strip_locations(doc: xml.dom.minidom.Document) -> None:
    for el in doc.getElementsByTagName("*"):
        if el.hasAttribute(LOCATION_ATTRIBUTE):
            el.removeAttribute(LOCATION_ATTRIBUTE)


def _keeps_locations(doc: xml.dom.minidom.Document) -> bool:
    """Only URDF output keeps the location attributes (the URDF parser reads them)."""
    root = doc.documentElement
    return root is not None and root.tagName == "robot" and detect_format(root.toxml()) == "urdf"


def _run(text: str, source: str, args: Mapping[str, str], tracker: _Tracker) -> xml.dom.minidom.Document:
    """Parse and process ``text`` with the hooks installed (raises on any failure)."""
    doc = _parse_located(text, source)
    xacro.init_stacks(None if source.startswith("<") else source)
    xacro.process_doc(doc, mappings={str(k): str(v) for k, v in args.items()})
    return doc


def expand(
    text: str, source: str, args: Mapping[str, str], sink: DiagnosticSink, resolver: ResourceResolver
) -> str | None:
    """Expand xacro text to plain XML, in this process (:func:`expand_bounded` is the one to call: this is
    its worker's side, and the tests').

    Args:
        text: the xacro document.
        source: its file name (relative includes resolve against its folder) or a
            synthetic name such as ``<string>.xacro`` (then against the working directory).
        args: values for ``$(arg name)``, overriding ``<xacro:arg>`` defaults.
        sink: receives ``XACRO_ERROR`` / ``XML_PARSE_ERROR`` diagnostics and xacro's warnings.
        resolver: resolves ``$(find pkg)``.

    Returns:
        The expanded XML (URDF output keeps per-element location attributes), or None
        after reporting an error.
    """
    tracker = _Tracker(sink, source)
    with _LOCK, _patched(resolver, tracker):
        try:
            doc = _run(text, source, args, tracker)
        except _IncludedXmlError as err:
            where = SourceLocation(err.location_file or source, err.line)
            sink.error(ErrorCode.XML_PARSE_ERROR, str(err), where)
            return None
        except Exception as err:  # xacro evaluates user expressions: any exception type can come out
            where = getattr(err, "gazelle_location", None) or tracker.location()
            sink.error(ErrorCode.XACRO_ERROR, f"xacro: {_describe(err)}{_macro_context()}", where)
            return None
        if not _keeps_locations(doc):
            _strip_locations(doc)
        root = doc.documentElement
        return root.toxml() if root is not None else None


def _expand_request(request: dict) -> tuple[str | None, list[tuple[str, str, str, str | None, int | None]]]:
    """The worker's side of :func:`expand_bounded`: plain data in, plain data out.

    It runs in the bounded helper process, so everything crossing over is picklable and small: the text,
    the arguments and the resolver's roots in; the expanded XML and the diagnostics as tuples (code,
    severity, message, file, line) out, rebuilt into :class:`Diagnostic` objects on the caller's side. The
    resolver is rebuilt from the same roots, so the worker reads exactly the files the caller could."""
    resolver = ResourceResolver(
        [Path(p) for p in request["extra_paths"]], request["env"], [Path(p) for p in request["trusted_dirs"]]
    )
    sink = DiagnosticSink(strict=request["strict"])
    out = expand(request["text"], source=request["source"], args=request["args"], sink=sink, resolver=resolver)
    items = [
        (
            d.code.value,
            d.severity.value,
            d.message,
            d.location.file if d.location else None,
            d.location.line if d.location else None,
        )
        for d in sink.items
    ]
    return out, items


_WORKER: Any = None


def _worker() -> Any:
    """The one bounded helper process of this process (see :mod:`._bounded`), started at the first expansion."""
    from ._bounded import BoundedWorker

    global _WORKER
    if _WORKER is None:
        _WORKER = BoundedWorker(_expand_request)
    return _WORKER


def expand_bounded(
    text: str,
    *,
    source: str,
    args: Mapping[str, str] | None = None,
    sink: DiagnosticSink,
    resolver: ResourceResolver,
) -> str | None:
    """:func:`expand` in a helper process bounded in time and memory (see :mod:`._bounded`).

    Use it for every file a user names: xacro evaluates Python, and ``${9**9**9}`` would
    otherwise hold the process (and its GIL) for minutes. Only files a user named on their own
    command line come here; a description that arrives as a string is never expanded.
    """
    from ._bounded import BoundExceeded
    from ._diagnostics import Diagnostic, Severity
    from ._resources import SEARCH_PATH_VARIABLES

    env = resolver.env if resolver.env is not None else os.environ
    request = {
        "text": text,
        "source": source,
        "args": {str(k): str(v) for k, v in (args or {}).items()},
        "strict": sink.strict,
        "extra_paths": [str(p) for p in resolver.extra_paths],
        "trusted_dirs": [str(p) for p in resolver.trusted_dirs],
        "env": {k: env[k] for k in (*SEARCH_PATH_VARIABLES, "AMENT_PREFIX_PATH") if k in env},
    }
    try:
        out, items = _worker().call(request, what=f"xacro expansion of {source}")
    except BoundExceeded as err:
        sink.error(ErrorCode.XACRO_ERROR, f"xacro: {err}", SourceLocation(source))
        return None
    diagnostics = [
        Diagnostic(ErrorCode(code), Severity(sev), msg, SourceLocation(file, line) if file is not None else None)
        for code, sev, msg, file, line in items
    ]
    sink.extend(diagnostics)
    return out


def read_description_file(path: str) -> str:
    """A description file a user named on a command line: xacro files are expanded (bounded, resolving
    relative to the file's own folder), others are read as they are. Raises ValueError with file:line
    diagnostics when the xacro fails."""
    from ._diagnostics import DiagnosticSink
    from ._resources import ResourceResolver

    p = Path(path)
    if not p.is_file():
        raise ValueError(f"{path}: no such file")
    text = p.read_text(encoding="utf-8")
    if p.suffix != ".xacro":
        return text
    sink = DiagnosticSink()
    out = expand_bounded(text, source=str(p), sink=sink, resolver=ResourceResolver().trusting(p.resolve().parent))
    if out is None:
        raise ValueError("; ".join(d.format() for d in sink.items) or f"{path}: xacro failed")
    return out


def xacro_main() -> int:
    """The venv's ``xacro`` command (``scripts/install_ros_packages.py`` installs it over the wheel's): xacro's
    own, whose ``$(find pkg)`` also finds the packages on ``GAZELLE_RESOURCE_PATH`` by their package.xml name,
    as ``gazelle spawn -file`` does, before the ament index. A launch file's ``Command(['xacro ', file])``
    and a user's shell then expand the files gazelle loads."""
    import sys

    resolver = ResourceResolver()
    ours = _find_with(resolver)
    ament = xacro_subst._eval_find

    def find(package: str) -> str:
        """``$(find pkg)`` for the ``xacro`` command: gazelle's resource roots first (a package found by its
        package.xml name), then the ament index as xacro itself looks; neither: xacro's own error, naming both."""
        try:
            return ours(package)
        except _PackageNotFound:
            pass
        try:
            return ament(package)  # xacro's own answer
        except Exception:
            raise xacro_subst.SubstitutionException(
                f"package '{package}' not found on GAZELLE_RESOURCE_PATH (by package.xml name) or in the "
                "ament index (AMENT_PREFIX_PATH)"
            ) from None

    xacro_subst._eval_find = find
    xacro_subst._eval_dict["find"] = find
    sys.argv[0] = "xacro"
    xacro.main()
    return 0
