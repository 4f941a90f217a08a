"""The root of every error gazelle raises on purpose: :class:`SimError`.

Every exception class of the package derives from it (``tests/project/test_architecture.py`` checks that, and
that no two share a name), so ``except SimError`` catches whatever gazelle refuses or fails at, and nothing
else. Each subclass keeps the built-in kind it also is (bad input a ``ValueError``, a failed run a
``RuntimeError``, a missing interface an ``ImportError``), so handlers written for those still catch it."""

from __future__ import annotations


class SimError(Exception):
    """Base class of every error gazelle raises on purpose."""
