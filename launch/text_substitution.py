"""TextSubstitution: literal text (launch.substitutions.TextSubstitution). On the ground floor beside the
Substitution base, as what every list of substitutions is normalized into (launch.utilities)."""

from __future__ import annotations

from .substitution import Substitution


class TextSubstitution(Substitution):
    """Literal text."""

    def __init__(self, *, text: str) -> None:
        if not isinstance(text, str):
            raise TypeError(f"TextSubstitution expects a string, got {type(text).__name__}")
        self.text = text

    def perform(self, context) -> str:
        return self.text

    def describe(self) -> str:
        return repr(self.text)
