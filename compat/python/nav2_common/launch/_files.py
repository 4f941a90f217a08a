"""Reading a parameter file and writing the rewritten copy, shared by nav2_common.launch's substitutions."""

from __future__ import annotations

import tempfile
from typing import Any

import yaml

from launch.substitutions import SubstitutionFailure


def read_text(path: str, who: str) -> str:
    """The text of ``path``; a SubstitutionFailure naming ``who`` and the file when it cannot be read."""
    try:
        with open(path, encoding="utf-8") as f:
            return f.read()
    except (OSError, UnicodeDecodeError) as err:
        reason = err.strerror if isinstance(err, OSError) and err.strerror else str(err)
        raise SubstitutionFailure(f"{who}: cannot read '{path}': {reason}") from None


def read_yaml(path: str, who: str) -> Any:
    """The YAML of ``path`` (plain data only); a SubstitutionFailure naming the file and line when it is not YAML."""
    try:
        return yaml.safe_load(read_text(path, who))
    except yaml.YAMLError as err:
        mark = getattr(err, "problem_mark", None)
        where = f"{path}:{mark.line + 1}" if mark is not None else path
        raise SubstitutionFailure(f"{who}: {where}: not valid YAML ({getattr(err, 'problem', None) or err})") from None


def write_temporary(text: str) -> str:
    """A new file (readable by its owner only, kept after the launch, as nav2_common's are) holding ``text``."""
    with tempfile.NamedTemporaryFile("w", encoding="utf-8", delete=False, suffix=".yaml") as f:
        f.write(text)
        return f.name
