"""The substitution language of XML and YAML launch files: ``$(name arg ...)`` inside text.

Written from the grammar of launch (Jazzy, launch/share/launch/frontend/grammar.lark) as a small
recursive-descent reader, so no parser generator is needed:

- at the top level, text runs up to the next ``$(``; ``\\$(`` is text; a backslash escapes the character
  after it (``\\x`` is ``x``), as launch's ``replace_escaped_characters``;
- ``$(`` IDENTIFIER, then arguments each after exactly one space, then ``)``; an identifier starts with a
  letter and holds letters, digits, ``_`` and ``-``;
- an argument is unquoted text and substitutions with no space, quote, parenthesis or ``$(`` (each of them
  may be escaped with a backslash), or a whole ``'...'`` or ``"..."`` template: inside one, text may hold
  spaces and the other quote, and substitutions nest with arguments of that same quoting.

The result is the list of substitutions launch would build: text as TextSubstitution, each ``$(...)``
made by the substitution exposed under its name (:mod:`launch.frontend.expose`).
"""

from __future__ import annotations

import re
from typing import Any

from ..substitution import Substitution
from ..text_substitution import TextSubstitution
from .expose import instantiate_substitution


class SubstitutionSyntaxError(ValueError):
    """Text that is not in the substitution language; says where (column, counted from 1)."""


def replace_escaped_characters(data: str) -> str:
    """``\\x`` -> ``x`` (launch.frontend.parse_substitution.replace_escaped_characters)."""
    return re.sub(r"\\(.)", r"\1", data)


_IDENT = re.compile(r"[A-Za-z][A-Za-z0-9_\-]*")


class _Reader:
    """One string being read; ``quote`` is the template's quote (``""`` outside any)."""

    def __init__(self, text: str) -> None:
        self.text = text
        self.pos = 0

    def at(self, token: str) -> bool:
        return self.text.startswith(token, self.pos)

    def escaped(self) -> bool:
        return self.pos > 0 and self.text[self.pos - 1] == "\\"

    def opens_substitution(self) -> bool:
        return self.at("$(") and not self.escaped()

    def fail(self, what: str) -> SubstitutionSyntaxError:
        return SubstitutionSyntaxError(f"{what} at column {self.pos + 1} of {self.text!r}")

    # -- templates -------------------------------------------------------------------------------------
    def template(self, quote: str) -> list[Substitution]:
        """Fragments up to the end (``quote`` empty) or to the closing quote (not consumed)."""
        out: list[Substitution] = []
        while self.pos < len(self.text):
            if quote and self.at(quote) and not self.escaped():
                return out
            if self.opens_substitution():
                out.append(self.substitution(quote))
                continue
            start = self.pos
            while self.pos < len(self.text) and not self.opens_substitution():
                if quote and self.at(quote) and not self.escaped():
                    break
                self.pos += 1
            out.append(TextSubstitution(text=replace_escaped_characters(self.text[start : self.pos])))
        if quote:
            raise self.fail(f"no closing {quote}")
        return out

    # -- substitutions ---------------------------------------------------------------------------------
    def substitution(self, quote: str) -> Substitution:
        self.pos += 2  # "$("
        match = _IDENT.match(self.text, self.pos)
        if match is None:
            raise self.fail("expected a substitution name after '$('")
        name = match.group(0)
        self.pos = match.end()
        args: list[list[Substitution]] = []
        while self.at(" "):
            self.pos += 1
            args.append(self.argument(quote))
        if not self.at(")"):
            raise self.fail(f"expected ')' or one space and an argument in $({name} ...)")
        self.pos += 1
        return instantiate_substitution(name, args)

    def argument(self, quote: str) -> list[Substitution]:
        """A quoted template (only outside any quotes) or unquoted parts."""
        if not quote and (self.at("'") or self.at('"')):
            inner = self.text[self.pos]
            self.pos += 1
            value = self.template(inner)
            self.pos += 1  # the closing quote
            return value
        parts: list[Substitution] = []
        while self.pos < len(self.text):
            if self.opens_substitution():
                parts.append(self.substitution(quote))
                continue
            start = self.pos
            while self.pos < len(self.text) and self._unquoted_char(quote):
                self.pos += 1
            if self.pos == start:
                break
            parts.append(TextSubstitution(text=replace_escaped_characters(self.text[start : self.pos])))
        if not parts:
            raise self.fail("expected an argument")
        return parts

    def _unquoted_char(self, quote: str) -> bool:
        """Whether the character here belongs to an unquoted argument (the grammar's *_RSTRING)."""
        c = self.text[self.pos]
        if c == " ":
            return False
        if c == "$":
            return not self.opens_substitution()
        if c in "()":
            return self.escaped()
        if c in "'\"":
            # outside quotes neither quote may appear bare; inside, only the template's own
            return self.escaped() or (bool(quote) and c != quote)
        return True


def parse_substitution(string_value: str) -> list[Substitution]:
    """The substitutions of ``string_value`` (launch.frontend.parse_substitution); an empty string is one
    empty text, as launch's."""
    if not string_value:
        return [TextSubstitution(text=string_value)]
    reader = _Reader(string_value)
    return reader.template("")


def parse_if_substitutions(value: Any) -> Any:
    """Substitutions in a text (or in each text of a list) when it has any, else the text itself; other
    values as they are (launch.frontend.parse_substitution.parse_if_substitutions). A list mixing kinds is
    refused as launch refuses it."""
    kinds: set[type] = set()

    def one(item: Any) -> Any:
        if isinstance(item, str):
            out = parse_substitution(item)
            if len(out) == 1 and isinstance(out[0], TextSubstitution):
                kinds.add(str)
                return out[0].text
            return out
        kinds.add(type(item))
        return item

    result = [one(x) for x in value] if isinstance(value, list) else one(value)
    if len(kinds) > 1:
        raise ValueError("The result is a non-uniform list")
    return result


__all__ = ["SubstitutionSyntaxError", "parse_if_substitutions", "parse_substitution", "replace_escaped_characters"]
