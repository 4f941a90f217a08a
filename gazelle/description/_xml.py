"""Shared XML helpers for the description loaders (URDF, xacro, SDF).

Stable functions (other loaders import them; keep their signatures):

- :func:`parse_xml` — text to an lxml root element, XML errors as ``XML_PARSE_ERROR``.
- :func:`element_location` — the :class:`SourceLocation` of an element (honours xacro annotations).
- :func:`to_config` — a read-only :class:`ConfigElement` copy of an element.
- :func:`parse_float`, :func:`parse_floats`, :func:`parse_bool` — strict value parsing (None on failure).
- :func:`local_name` — an element's tag without its namespace.
- :data:`LOCATION_ATTRIBUTE`, :func:`encode_location`, :func:`decode_location` — the attribute the
  xacro expander puts on every element to say which file and line it came from.

Nothing here reports anything except :func:`parse_xml`; callers decide the code and severity.
"""

from __future__ import annotations

import math
import re
from urllib.parse import quote, unquote

from lxml import etree

from ._diagnostics import DiagnosticSink, ErrorCode, SourceLocation
from ._model import ConfigElement

LOCATION_ATTRIBUTE = "gazelle_source"
"""Attribute added by the xacro expander: ``<quoted file>:<line>`` of the element's origin."""

_SAFE_PATH_CHARS = "/\\:._-~+@ "
_TRUE = frozenset({"true", "1"})
_FALSE = frozenset({"false", "0"})


def encode_location(file: str, line: int | None) -> str:
    """The :data:`LOCATION_ATTRIBUTE` value for ``file`` and ``line``.

    The file name is percent-quoted so the value contains no ``$`` (which xacro would evaluate).
    """
    return f"{quote(file, safe=_SAFE_PATH_CHARS)}:{line if line is not None else ''}"


def decode_location(value: str) -> SourceLocation | None:
    """Inverse of :func:`encode_location`; None when ``value`` is not such a value."""
    file, sep, line = value.rpartition(":")
    if not sep or not file:
        return None
    return SourceLocation(unquote(file), int(line) if line.isdigit() else None)


def _parser() -> etree.XMLParser:
    # No entity expansion, no DTD or network access: model files are data, not programs.
    return etree.XMLParser(
        resolve_entities=False, no_network=True, load_dtd=False, huge_tree=False, remove_comments=False
    )


_COMMENT = re.compile(r"<!--(.*?)-->", re.S)


def relax_comments(text: str) -> tuple[str, list[int]]:
    """``text`` with every ``--`` inside a comment (and a ``-`` right before ``-->``) blanked, and the
    lines of those comments. XML forbids them; TinyXML, and so Gazebo, accepts them, and 19 of
    gz-sim's example worlds have them. Blanking keeps every line and column where it was."""
    if "--" not in text:
        return text, []
    lines: list[int] = []

    def fix(m: re.Match[str]) -> str:
        body = m.group(1)
        if "--" not in body and not body.endswith("-"):
            return m.group(0)
        lines.append(text.count("\n", 0, m.start()) + 1)
        body = body.replace("--", "  ")
        if body.endswith("-"):
            body = body[:-1] + " "
        return f"<!--{body}-->"

    return _COMMENT.sub(fix, text), lines


def parse_xml(text: str, *, source: str, sink: DiagnosticSink) -> etree._Element | None:
    """Parse XML text into its root element.

    Args:
        text: the document.
        source: file name for diagnostics.
        sink: receives ``XML_PARSE_ERROR`` (with the parser's line) on failure.

    Returns:
        The root element, or None after reporting an error.
    """
    fixed, lines = relax_comments(text)
    for line in lines:
        sink.warning(
            ErrorCode.XML_PARSE_ERROR,
            "comment contains '--', which XML forbids; accepted as TinyXML (Gazebo) accepts it",
            SourceLocation(source, line),
        )
    try:
        root = etree.fromstring(fixed.encode("utf-8"), _parser())
    except etree.XMLSyntaxError as err:
        line = err.lineno if isinstance(err.lineno, int) and err.lineno > 0 else None
        msg = getattr(err, "msg", None) or str(err)
        sink.error(ErrorCode.XML_PARSE_ERROR, f"malformed XML: {msg}", SourceLocation(source, line))
        return None
    except ValueError as err:  # e.g. text lxml refuses outright
        sink.error(ErrorCode.XML_PARSE_ERROR, f"malformed XML: {err}", SourceLocation(source))
        return None
    if root is None:
        sink.error(ErrorCode.XML_PARSE_ERROR, "malformed XML: empty document", SourceLocation(source))
    return root


def element_location(element: etree._Element, source: str) -> SourceLocation:
    """Where ``element`` came from.

    An element expanded by xacro carries :data:`LOCATION_ATTRIBUTE` (its original file and
    line); elements xacro created without one take their nearest annotated ancestor's.
    Plain documents use the parser's line in ``source``.
    """
    node: etree._Element | None = element
    while node is not None:
        value = node.get(LOCATION_ATTRIBUTE)
        if value is not None:
            loc = decode_location(value)
            if loc is not None:
                return loc
        node = node.getparent()
    line = element.sourceline
    return SourceLocation(source, line if isinstance(line, int) else None)


def local_name(element: etree._Element) -> str:
    """The tag without a ``{namespace}`` part (``prefix:name`` when a prefix is declared)."""
    tag = element.tag
    if not isinstance(tag, str):
        return ""
    if tag.startswith("{"):
        name = tag.split("}", 1)[1]
        return f"{element.prefix}:{name}" if element.prefix else name
    return tag


def child_elements(element: etree._Element) -> list[etree._Element]:
    """Direct child elements, skipping comments and processing instructions."""
    return [c for c in element if isinstance(c.tag, str)]


def to_config(element: etree._Element, source: str) -> ConfigElement:
    """A read-only copy of ``element`` and its subtree (plugin, sensor and extension blocks).

    Text is stripped; comments are dropped; the xacro location attribute is not copied
    but becomes each node's ``location``.
    """
    attributes = tuple((str(k), str(v)) for k, v in element.attrib.items() if k != LOCATION_ATTRIBUTE)
    return ConfigElement(
        tag=local_name(element),
        attributes=attributes,
        text=(element.text or "").strip(),
        children=tuple(to_config(c, source) for c in child_elements(element)),
        location=element_location(element, source),
    )


def parse_float(text: str | None) -> float | None:
    """A finite float, or None when ``text`` is missing or not a finite number."""
    if text is None:
        return None
    try:
        value = float(text.strip())
    except ValueError:
        return None
    return value if math.isfinite(value) else None


def parse_floats(text: str | None, count: int | None = None) -> tuple[float, ...] | None:
    """Whitespace-separated finite floats; None if any is invalid or the count differs.

    The one reader of number lists for URDF attributes and SDF elements alike. Any whitespace separates
    (xacro output often has newlines and doubled spaces inside ``xyz``), and a count that differs is a failure
    rather than a truncation or a padding: ``xyz="0 0"`` is a mistake to report, not a point at z = 0."""
    if text is None:
        return None
    parts = text.split()
    if count is not None and len(parts) != count:
        return None
    values: list[float] = []
    for part in parts:
        v = parse_float(part)
        if v is None:
            return None
        values.append(v)
    return tuple(values)


def parse_bool(text: str | None) -> bool | None:
    """``true``/``1`` or ``false``/``0`` (case-insensitive); None otherwise."""
    if text is None:
        return None
    value = text.strip().lower()
    if value in _TRUE:
        return True
    if value in _FALSE:
        return False
    return None
