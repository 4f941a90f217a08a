"""Make real-world SDF text acceptable to lxml without moving any line.

Gazebo (tinyxml2) accepts two things a namespace-aware XML parser rejects:

* anything (comments, blank lines) before the ``<?xml ...?>`` declaration. We blank the
  declaration out (spaces, newlines kept), which makes the leading comments legal;
* element and attribute names with an undeclared prefix or a double colon, such as
  ``<gz::system_priority>`` or ``<ignition:foo>``. We replace every ``:`` in such a name
  by :data:`COLON` (a legal name character) and turn it back with :func:`decode_name`.

Both rewrites keep every newline, so lxml's line numbers stay the file's.
"""

from __future__ import annotations

import re

from ._model import ConfigElement

COLON = "\u00b7"
"""Stands for ``:`` inside element and attribute names while lxml parses (MIDDLE DOT)."""

_DECL = re.compile(r"<\?xml\s[^>]*?\?>", re.S)
_LEADING_JUNK = re.compile(r"\A(?:\s|<!--.*?-->)*\Z", re.S)
# Markup tokens: comments, CDATA, processing instructions and doctype pass through;
# tags are rewritten. Quoted attribute values may contain '>' so they are matched whole.
_TOKEN = re.compile(
    r"<!--.*?-->|<!\[CDATA\[.*?\]\]>|<\?.*?\?>|<!.*?>"
    r"|<(/?)([^\s/>!?]+)((?:\s+[^\s=/>]+\s*=\s*(?:\"[^\"]*\"|'[^']*'))*)(\s*/?\s*)>",
    re.S,
)
_ATTR = re.compile(r"([^\s=/>]+)(\s*=\s*)(\"[^\"]*\"|'[^']*')")


def _blank(text: str) -> str:
    return "".join(c if c == "\n" else " " for c in text)


def _encode(name: str) -> str:
    return name.replace(":", COLON)


def _rewrite_tag(match: re.Match[str]) -> str:
    """One tag of :data:`_TOKEN` with the colons of its element and attribute names encoded (see the module
    docstring); comments, CDATA, processing instructions, the doctype and tags without a colon come back as
    they were. ``xmlns:`` and ``xml:`` attributes keep theirs: they are real namespace syntax lxml needs, and a
    prefix they declare is then legal. Attribute values are never touched (a ``model://`` URI has colons)."""
    name = match.group(2)
    if name is None:  # comment, CDATA, PI, doctype
        return match.group(0)
    attrs = match.group(3) or ""
    if ":" not in name and ":" not in attrs:
        return match.group(0)

    def attr(m: re.Match[str]) -> str:
        key = m.group(1)
        if ":" in key and not key.startswith(("xmlns:", "xml:")):
            key = _encode(key)
        return key + m.group(2) + m.group(3)

    return f"<{match.group(1)}{_encode(name)}{_ATTR.sub(attr, attrs)}{match.group(4)}>"


def prepare(text: str) -> tuple[str, bool]:
    """The text lxml should parse, and whether any name was rewritten.

    Line numbers are unchanged; see the module docstring for what is rewritten.
    """
    if text.startswith("\ufeff"):
        text = text[1:]
    decl = _DECL.search(text)
    if decl is not None and decl.start() > 0 and _LEADING_JUNK.match(text[: decl.start()]):
        text = text[: decl.start()] + _blank(decl.group(0)) + text[decl.end() :]
    if ":" not in text:
        return text, False
    rewritten = _TOKEN.sub(_rewrite_tag, text)
    return rewritten, rewritten != text


def decode_name(name: str) -> str:
    """Undo the ``:`` substitution of :func:`prepare` in an element or attribute name."""
    return name.replace(COLON, ":")


def decode_config(config: ConfigElement) -> ConfigElement:
    """A copy of ``config`` with ``:`` restored in every tag and attribute name."""
    return ConfigElement(
        tag=decode_name(config.tag),
        attributes=tuple((decode_name(k), v) for k, v in config.attributes),
        text=config.text,
        children=tuple(decode_config(c) for c in config.children),
        location=config.location,
    )
