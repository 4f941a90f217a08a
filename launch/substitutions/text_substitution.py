"""``launch.substitutions.text_substitution`` (Jazzy's module path): TextSubstitution is defined on the ground
floor, launch/text_substitution.py, so that normalize_to_list_of_substitutions (launch.utilities) can make
literal text without importing this package, whose substitutions use it."""

from ..text_substitution import TextSubstitution

__all__ = ["TextSubstitution"]
