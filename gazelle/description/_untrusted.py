"""Reading files and YAML that someone else may have written, with bounds.

Two ways a small input becomes a large cost, each closed here once for every reader:

* **A path that is not a file.** A FIFO blocks ``open`` for good, ``/dev/zero`` never ends, a 10 GB log
  fills memory. :func:`read_regular_file` opens without blocking, refuses anything but a regular file,
  and reads at most ``max_bytes``.
* **YAML aliases.** ``&a [1,1,...]`` then ``&b [*a,*a,...]``: PyYAML shares aliased objects, so a
  693-byte file loads at once, but every consumer that walks it (flattening parameters, filling a
  message) expands it: 2.1 million parameters, or a 9-million-float trajectory from 30 KB.
  :func:`safe_load_bounded` composes the document (aliases still shared), counts the nodes it would
  have once expanded, refuses more than ``max_nodes`` and any recursive alias, and an integer literal
  longer than :data:`MAX_YAML_INT_CHARS` (past Python's int-string-conversion limit, PyYAML raised a
  bare ValueError), and only then constructs it.

Errors are :class:`UntrustedInputError` with the file (and line where YAML knows it); they never echo
the file's content, so a refusal logged on ``/rosout`` cannot leak what it refused.
"""

from __future__ import annotations

import errno
import os
import stat
from pathlib import Path
from typing import Any

import yaml

from .._errors import SimError

MAX_PARAMS_FILE_BYTES = 4 * 1024 * 1024
"""A parameters file larger than this is refused (MoveIt's and ros2_control's are a few KB)."""
MAX_YAML_NODES = 200_000
"""The most YAML nodes (scalars, sequences, mappings) a document may hold once its aliases are
expanded: a JointTrajectory of 2,000 points of 7 joints with positions, velocities and accelerations
is ~50,000; TurtleBot3's, Panda's and r6bot's parameter files are under 500."""
MAX_YAML_INT_CHARS = 1000
"""The longest integer literal a document may hold (int64's largest is 19 digits). PyYAML reads an integer
with ``int()``, whose string-conversion limit (``sys.get_int_max_str_digits()``, 4,300 decimal digits by
default) raises a ValueError that is not a YAMLError: a 5,000-digit ``depth`` was a traceback. Below that
limit in every base (1,000 hex digits are 1,205 decimal ones), so a value read can always be printed,
and with ``PYTHONINTMAXSTRDIGITS=0`` (no limit) a megabyte of digits is not a quadratic-time conversion."""

_Loader: Any = getattr(yaml, "CSafeLoader", yaml.SafeLoader)


PARAMETERS_TEXT_TAG = "gazelle_parameters_text"
"""A ``<plugin>`` child that carries a ros2_control ``<parameters>`` file's text, read by ``gazelle spawn -file``
beside the robot file with the user's own rights (the server reads no file of the user's): parsed by the
controller manager with the same bounds as a file, as the spawner's ``<ctrl>.params_file_yaml``."""


class UntrustedInputError(SimError, ValueError):
    """A file or text refused by a bound; the message names it (and the line) but never its content."""


def read_regular_file(path: str | os.PathLike[str], max_bytes: int, what: str = "file") -> str:
    """The UTF-8 text of ``path``, which must be a regular file of at most ``max_bytes``.

    Opened with ``O_NONBLOCK``: a FIFO with no writer does not block the caller (it is then refused as
    not a regular file), and neither does a device.

    Raises:
        UntrustedInputError: not a regular file, too large, unreadable, or not UTF-8.
    """
    p = Path(path)
    try:
        fd = os.open(p, os.O_RDONLY | os.O_NONBLOCK | getattr(os, "O_CLOEXEC", 0))
    except OSError as err:
        raise UntrustedInputError(f"{p}: cannot read the {what}: {err.strerror or err}") from None
    try:
        info = os.fstat(fd)
        if not stat.S_ISREG(info.st_mode):
            raise UntrustedInputError(f"{p}: the {what} is not a regular file (a FIFO, device or folder is never read)")
        if info.st_size > max_bytes:
            raise UntrustedInputError(f"{p}: the {what} has {info.st_size} bytes, more than the {max_bytes} allowed")
        chunks: list[bytes] = []
        left = max_bytes + 1
        while left > 0:
            try:
                chunk = os.read(fd, min(left, 1 << 20))
            except OSError as err:
                if err.errno == errno.EAGAIN:
                    continue
                raise UntrustedInputError(f"{p}: cannot read the {what}: {err.strerror or err}") from None
            if not chunk:
                break
            chunks.append(chunk)
            left -= len(chunk)
        data = b"".join(chunks)
        if len(data) > max_bytes:  # it grew while being read
            raise UntrustedInputError(f"{p}: the {what} has more than the {max_bytes} bytes allowed")
    finally:
        os.close(fd)
    try:
        return data.decode("utf-8")
    except UnicodeDecodeError as err:
        raise UntrustedInputError(f"{p}: the {what} is not UTF-8 text (byte {err.start})") from None


def yaml_problem(err: Exception, where: str) -> str:
    """A YAML parse error as ``where:line: not valid YAML: problem`` (the line when PyYAML knows it).

    PyYAML's ``problem`` is a description of the grammar (``mapping values are not allowed here``), not
    the text; its ``context`` and ``str(err)`` quote the text, so they are left out."""
    mark = getattr(err, "problem_mark", None)
    line = f":{mark.line + 1}" if mark is not None else ""
    problem = getattr(err, "problem", None) or type(err).__name__
    return f"{where}{line}: not valid YAML: {problem}"


def _expanded_size(root: yaml.Node, limit: int, where: str) -> int:
    """How many nodes ``root`` holds with every alias expanded (stops counting past ``limit``).

    Shared nodes are counted once per use, as a consumer walking the loaded data would visit them; a
    node reached again while it is being counted is a recursive alias and is refused."""
    size: dict[int, int] = {}
    open_: set[int] = set()
    stack: list[tuple[yaml.Node, bool]] = [(root, False)]
    while stack:
        node, children_done = stack.pop()
        key = id(node)
        if children_done:
            open_.discard(key)
            total = 1
            for child in _children(node):
                total += size[id(child)]
                if total > limit:
                    break
            size[key] = min(total, limit + 1)
            if size[key] > limit:
                line = node.start_mark.line + 1 if node.start_mark is not None else 0
                raise UntrustedInputError(
                    f"{where}:{line}: the YAML expands to more than {limit} values (through its aliases '*')"
                )
            continue
        if key in size:
            continue
        _check_scalar(node, where)
        if key in open_:
            line = node.start_mark.line + 1 if node.start_mark is not None else 0
            raise UntrustedInputError(f"{where}:{line}: a YAML alias refers to itself (a recursive structure)")
        open_.add(key)
        stack.append((node, True))
        for child in _children(node):
            if id(child) in open_:
                line = child.start_mark.line + 1 if child.start_mark is not None else 0
                raise UntrustedInputError(f"{where}:{line}: a YAML alias refers to itself (a recursive structure)")
            if id(child) not in size:
                stack.append((child, False))
    return size[id(root)]


def _check_scalar(node: yaml.Node, where: str) -> None:
    """Refuse an integer literal longer than :data:`MAX_YAML_INT_CHARS` (its line named, not its digits)."""
    if (
        isinstance(node, yaml.ScalarNode)
        and node.tag == "tag:yaml.org,2002:int"
        and len(node.value) > MAX_YAML_INT_CHARS
    ):
        line = node.start_mark.line + 1 if node.start_mark is not None else 0
        raise UntrustedInputError(
            f"{where}:{line}: an integer of {len(node.value)} characters (at most {MAX_YAML_INT_CHARS})"
        )


def _children(node: yaml.Node) -> list[yaml.Node]:
    if isinstance(node, yaml.SequenceNode):
        return list(node.value)
    if isinstance(node, yaml.MappingNode):
        return [n for pair in node.value for n in pair]
    return []


def safe_load_bounded(text: str, where: str = "<string>", max_nodes: int = MAX_YAML_NODES) -> Any:
    """``yaml.safe_load`` that refuses a document of more than ``max_nodes`` values once expanded.

    Raises:
        UntrustedInputError: YAML that does not parse (with its line), expands past the bound, has a
            recursive alias or an integer literal of more than :data:`MAX_YAML_INT_CHARS` characters.
    """
    loader = _Loader(text)
    try:
        try:
            node = loader.get_single_node()
        except yaml.YAMLError as err:
            raise UntrustedInputError(yaml_problem(err, where)) from None
        if node is None:
            return None
        _expanded_size(node, max_nodes, where)
        try:
            return loader.construct_document(node)
        except yaml.YAMLError as err:
            raise UntrustedInputError(yaml_problem(err, where)) from None
        except RecursionError:
            raise UntrustedInputError(f"{where}: the YAML is nested too deeply") from None
        except ValueError as err:  # a conversion PyYAML does not wrap in a YAMLError
            raise UntrustedInputError(f"{where}: not valid YAML: {str(err)[:200]}") from None
    finally:
        loader.dispose()
