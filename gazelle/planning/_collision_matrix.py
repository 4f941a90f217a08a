"""MoveIt's allowed collision matrix (ACM) over gazelle's planning scene.

MoveIt's planning scene starts with every robot link that has collision geometry in the matrix, each pair
not allowed, and the SRDF's ``<disable_collisions>`` pairs allowed (planning_scene.cpp, ``initialize``;
collision_matrix.cpp). A client reads it with ``get_planning_scene`` and sends a whole new one back with
``apply_planning_scene``: MoveIt then *replaces* its matrix with the message's
(``setPlanningSceneDiffMsg``), so a pair the message allows is no longer checked and a pair it leaves out
or forbids is checked, the SRDF's pairs included. pymoveit2's ``allow_collisions(id, allow)`` works that
way: it reads the matrix, adds a row and a column for ``id`` and applies it.

Here the matrix is kept as the names it covers and the pairs it allows; :class:`RobotScene` applies it to
roboplan's collision pairs (links by name, a world object by its geometries) whenever the scene changes.
What gazelle allows on its own besides (an attached object with its link and ``touch_links``, world
objects with the links no plan moves and with each other) is not part of the matrix and stays allowed.
"""

from __future__ import annotations

from collections.abc import Iterable, Sequence
from dataclasses import dataclass, field


@dataclass
class CollisionMatrix:
    """The names the matrix covers, in order, and the pairs among them whose collisions are allowed."""

    names: list[str]
    allowed: set[frozenset[str]] = field(default_factory=set)

    @classmethod
    def initial(cls, links: Sequence[str], disabled: Iterable[tuple[str, str]]) -> CollisionMatrix:
        """MoveIt's starting matrix: ``links`` (those with collision geometry), the SRDF pairs allowed."""
        known = set(links)
        return cls(list(links), {frozenset(p) for p in disabled if p[0] in known and p[1] in known})

    def rows(self) -> list[list[bool]]:
        """``entry_values``: row i, column j says whether names[i] and names[j] may collide."""
        return [[frozenset((a, b)) in self.allowed for b in self.names] for a in self.names]

    def is_allowed(self, a: str, b: str) -> bool:
        return frozenset((a, b)) in self.allowed

    @classmethod
    def from_rows(cls, names: Sequence[str], rows: Sequence[Sequence[bool]]) -> CollisionMatrix:
        """The matrix of an ``AllowedCollisionMatrix`` message; a row count or length that does not match the
        names is a ValueError naming it (MoveIt's AllowedCollisionMatrix constructor refuses it too). A pair
        is read from the upper triangle, row i's cell j for j > i, as that constructor reads it
        (collision_matrix.cpp); the lower triangle is not read."""
        if len(rows) != len(names):
            raise ValueError(f"{len(names)} entry_names but {len(rows)} entry_values")
        for i, row in enumerate(rows):
            if len(row) != len(names):
                raise ValueError(f"entry_values[{i}] has {len(row)} values for {len(names)} entry_names")
        allowed = {frozenset((a, b)) for i, a in enumerate(names) for j, b in enumerate(names) if i < j and rows[i][j]}
        return cls(list(dict.fromkeys(names)), allowed)

    def pairs_with(self, name: str) -> list[tuple[str, bool]]:
        """Every other name of the matrix with whether its collisions with ``name`` are allowed."""
        if name not in self.names:
            return []
        return [(other, frozenset((name, other)) in self.allowed) for other in self.names if other != name]
